// The include search path and the standard library's location.
#include "include_search.hpp"

#include <cstdlib>
#include <sstream>

namespace crt::lang {

namespace fs = std::filesystem;

std::vector<fs::path> IncludeSearch::folders(const fs::path& scriptFolder) const {
    std::vector<fs::path> result{scriptFolder};
    for (const std::string& dir : dirs) result.push_back(fs::absolute(dir));
    if (const char* crtPath = std::getenv("CRT_PATH")) {
        std::stringstream list(crtPath);
        for (std::string dir; std::getline(list, dir, ':');) {
            if (!dir.empty()) result.push_back(fs::absolute(dir));
        }
    }
    if (!stdlibDir.empty()) result.push_back(fs::absolute(stdlibDir));
    return result;
}

fs::path IncludeSearch::find(const std::string& name, const fs::path& scriptFolder) const {
    std::error_code error;
    if (fs::path(name).is_absolute()) return fs::is_regular_file(name, error) ? fs::path(name) : fs::path();
    for (const fs::path& dir : folders(scriptFolder)) {
        if (fs::is_regular_file(dir / name, error)) return dir / name;
    }
    return {};
}

// Only a program run from the build tree's bin/ falls back on the source tree: an installed
// program must not read a source tree that happens to be on the machine, or be changed by it.
std::string defaultStdlibDir() {
    std::error_code error;
    fs::path program = fs::canonical("/proc/self/exe", error);
    if (error) return CRT_SOURCE_STDLIB_DIR;
    fs::path programDir = program.parent_path();
    if (fs::equivalent(programDir, CRT_BUILD_PROGRAM_DIR, error)) return CRT_SOURCE_STDLIB_DIR;
    return (programDir.parent_path() / "share" / "crt" / "stdlib").string();
}

} // namespace crt::lang
