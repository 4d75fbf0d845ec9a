// Where `include "name"` looks: one search path for every reader of scripts.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace crt::lang {

class FileAccess;

/// Where an include was found, or why it may not be read.
struct FoundInclude {
    std::filesystem::path path; ///< empty when there is none
    std::string refusal;        ///< why the name may not be read (FileAccess), else empty
};

/// The include search path: the including script's folder, then the -I folders in order,
/// then the folders of the CRT_PATH environment variable (separated by ':'), then the
/// standard library.
struct IncludeSearch {
    std::vector<std::string> dirs; ///< -I, in order
    std::string stdlibDir;         ///< the standard library; empty: none

    /// The folders searched for an include written in a script of `scriptFolder`, in order.
    std::vector<std::filesystem::path> folders(const std::filesystem::path& scriptFolder) const;
    /// The file that `include "name"` in a script of `scriptFolder` reads: an absolute name
    /// as it is, else the first folder that has it, among the files `access` allows. When
    /// none is found but a candidate was refused (outside the roots, a folder …), the first
    /// refusal says why.
    FoundInclude find(const std::string& name, const std::filesystem::path& scriptFolder,
                      const FileAccess& access) const;
};

/// The standard library that came with the running program: the source tree's `stdlib/` for
/// a program in the build tree's `bin/`, else `<prefix>/share/crt/stdlib` for a program in
/// `<prefix>/bin` or a helper program in `<prefix>/lib/crt`.
std::string defaultStdlibDir();

} // namespace crt::lang
