// crtc --preview runs the program crtc-preview in its place. The preview's HTTP server is
// Debian's cpp-httplib, a shared library built with OpenSSL and brotli: linked into crtc, the
// dynamic loader would map and initialise them for every check and render too.
#include "preview_launch.hpp"

#include "companion_files.hpp"
#include "terminal_text.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace crt::crtc {

namespace fs = std::filesystem;

int launchPreview(char** argv) {
    constexpr const char* kProgramName = "crtc-preview";
    const std::vector<fs::path> candidates = companionCandidates(kProgramName);
    for (const fs::path& path : candidates) {
        std::error_code ec;
        if (!fs::exists(path, ec)) continue;
        std::cout.flush();
        execv(path.c_str(), argv);
        std::cerr << "crtc: cannot start the preview program " << lang::terminalSafe(path.string())
                  << ": " << std::strerror(errno) << "\n";
        return 2;
    }
    std::cerr << "crtc: the preview program " << kProgramName << " was not found; looked for "
              << lang::terminalSafe(describeCandidates(candidates)) << "\n";
    return 2;
}

} // namespace crt::crtc
