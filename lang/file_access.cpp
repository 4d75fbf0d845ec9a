// The read rule: resolve the name, compare it with the roots, then look at what it is.
#include "file_access.hpp"

#include "include_search.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace crt::lang {

namespace fs = std::filesystem;

namespace {

/// Why a file of this type is not read as a script, image or mesh; empty for a regular file.
std::string notAFileReason(mode_t mode) {
    if (S_ISREG(mode)) return {};
    if (S_ISDIR(mode)) return "is a folder, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a file";
    if (S_ISSOCK(mode)) return "is a socket, not a file";
    return "is not a regular file";
}

} // namespace

FileAccess::FileAccess(const ReadPermissions& permissions)
    : allowAll_(permissions.allowAll), howToAllow_(permissions.howToAllow) {
    for (const std::string& folder : permissions.allowRead) addRoot(folder);
}

void FileAccess::addRoot(const fs::path& folder) {
    std::error_code error;
    fs::path resolved = fs::weakly_canonical(fs::absolute(folder, error), error);
    if (error) return;
    // A folder that is missing still counts: a file looked for in it is then reported as not
    // found, not as outside the folders a script may read (it grants nothing, having nothing).
    if (fs::exists(resolved, error) && !fs::is_directory(resolved, error)) return;
    roots_.push_back(std::move(resolved));
}

bool isUnder(const fs::path& path, const fs::path& folder) {
    auto [folderEnd, pathAt] =
        std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
    return folderEnd == folder.end();
}

bool FileAccess::inside(const fs::path& resolved) const {
    return std::any_of(roots_.begin(), roots_.end(),
                       [&](const fs::path& root) { return isUnder(resolved, root); });
}

FileCheck FileAccess::check(const fs::path& path) const {
    FileCheck result;
    std::error_code error;
    result.resolved = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) result.resolved = fs::absolute(path, error).lexically_normal();
    // Refused before looking whether it exists: the answer says nothing about the machine.
    if (!allowAll_ && !inside(result.resolved)) {
        result.kind = FileCheck::Kind::Outside;
        result.reason = "is outside the folders a script may read (its own folder, the include "
                        "path, the standard library and the asset roots); allow it with " +
                        howToAllow_;
        return result;
    }
    struct stat status {};
    if (::stat(result.resolved.c_str(), &status) != 0) {
        if (errno == ENOENT || errno == ENOTDIR) return result; // Missing
        result.kind = FileCheck::Kind::Refused;
        result.reason = std::string("cannot be read: ") + std::strerror(errno);
        return result;
    }
    result.reason = notAFileReason(status.st_mode);
    result.kind = result.reason.empty() ? FileCheck::Kind::Readable : FileCheck::Kind::Refused;
    return result;
}

FileAccess scriptFileAccess(const fs::path& scriptFolder, const IncludeSearch& includes,
                            const std::vector<std::string>& assetRoots,
                            const ReadPermissions& permissions) {
    FileAccess access(permissions);
    for (const fs::path& folder : includes.folders(scriptFolder)) access.addRoot(folder);
    for (const std::string& root : assetRoots) access.addRoot(root);
    return access;
}

} // namespace crt::lang
