// The include search path and the standard library's location.
#include "include_search.hpp"

#include "file_access.hpp"

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

FoundInclude IncludeSearch::find(const std::string& name, const fs::path& scriptFolder,
                                 const FileAccess& access) const {
    std::vector<fs::path> candidates;
    if (fs::path(name).is_absolute()) candidates.emplace_back(name);
    else
        for (const fs::path& dir : folders(scriptFolder)) candidates.push_back(dir / name);
    FoundInclude result;
    for (const fs::path& candidate : candidates) {
        const FileCheck check = access.check(candidate);
        if (check.readable()) return {candidate, {}};
        if (check.refused() && result.refusal.empty()) result.refusal = check.reason;
    }
    return result;
}

// Only a program run from the build tree's bin/ falls back on the source tree: an installed
// program must not read a source tree that happens to be on the machine, or be changed by it.
std::string defaultStdlibDir() {
    std::error_code error;
    fs::path program = fs::canonical("/proc/self/exe", error);
    if (error) return CRT_SOURCE_STDLIB_DIR;
    fs::path programDir = program.parent_path();
    if (fs::equivalent(programDir, CRT_BUILD_PROGRAM_DIR, error)) return CRT_SOURCE_STDLIB_DIR;
    // Installed, a program is in <prefix>/bin and a helper program in <prefix>/lib/crt.
    fs::path prefix = programDir.parent_path();
    if (programDir.filename() == "crt" && prefix.filename() == "lib") prefix = prefix.parent_path();
    return (prefix / "share" / "crt" / "stdlib").string();
}

} // namespace crt::lang
