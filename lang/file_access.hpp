// Which files a script may read: one rule for includes, images and meshes, in crtc and crt-lsp.
//
// A script may read files under its own folder, the include search path (-I, CRT_PATH, the
// standard library), the asset roots (--assets) and the folders the user allowed
// (--allow-read); anything else is refused, whether or not it exists, so that an error never
// tells a script what the machine holds. Names are resolved (symbolic links, "..") before
// they are compared with the roots. Folders, devices, FIFOs and sockets are never read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace crt::lang {

struct IncludeSearch;

/// What the user allowed beyond the script's own roots.
struct ReadPermissions {
    std::vector<std::string> allowRead; ///< --allow-read DIR: further folders
    bool allowAll = false;              ///< --allow-read-all: any file, as before the rule
    /// How to allow another folder, for the refusal message (crt-lsp names its own settings).
    std::string howToAllow = "--allow-read DIR (or --allow-read-all)";
};

/// The answer about one file.
struct FileCheck {
    enum class Kind { Readable, Missing, Outside, Refused }; ///< Outside: not under any root
    Kind kind = Kind::Missing;
    std::filesystem::path resolved; ///< the path with links and ".." resolved
    std::string reason;             ///< why it is refused: "is a folder", "is outside …"
    bool readable() const { return kind == Kind::Readable; }
    bool refused() const { return kind == Kind::Outside || kind == Kind::Refused; }
};

/// The folders a script may read, and the check of a file against them.
class FileAccess {
  public:
    /// Allows nothing but what `permissions` allows.
    explicit FileAccess(const ReadPermissions& permissions = {});
    /// Allows everything under `folder` (resolved now; a folder that does not exist is skipped).
    void addRoot(const std::filesystem::path& folder);
    FileCheck check(const std::filesystem::path& path) const;

  private:
    bool inside(const std::filesystem::path& resolved) const;

    std::vector<std::filesystem::path> roots_;
    bool allowAll_;
    std::string howToAllow_;
};

/// Whether `path` is `folder` or below it, component by component ("/a/bc" is not below
/// "/a/b"); both as given, nothing resolved.
bool isUnder(const std::filesystem::path& path, const std::filesystem::path& folder);

/// The access of a script in `scriptFolder`: that folder, the include search path, the asset
/// roots and the allowed folders.
FileAccess scriptFileAccess(const std::filesystem::path& scriptFolder, const IncludeSearch& includes,
                            const std::vector<std::string>& assetRoots,
                            const ReadPermissions& permissions);

} // namespace crt::lang
