// Where crtc finds the files it keeps beside itself (see companion_files.hpp).
#include "companion_files.hpp"

#include <system_error>

namespace crt::crtc {

namespace fs = std::filesystem;

std::vector<fs::path> companionCandidates(const std::string& fileName) {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path dir = exe.parent_path();
    return {dir / fileName, (dir / ".." / "lib" / "crt" / fileName).lexically_normal()};
}

std::string describeCandidates(const std::vector<fs::path>& candidates) {
    if (candidates.empty()) return "the executable's folder, which is unknown";
    std::string text;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        text += (i ? " and " : "") + candidates[i].string();
    return text;
}

} // namespace crt::crtc
