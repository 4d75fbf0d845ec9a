// The temporary file an output is written to before it is renamed over its target.
//
// A predictable name beside the target could be planted in advance (a symlink to another
// file, which an ordinary open would follow and overwrite), so the name is random and the
// file is created with O_EXCL | O_NOFOLLOW. Every live temporary is also listed in a fixed
// table that a signal handler can empty with unlink() alone (removeAllTemporaries), so that a
// program stopped by a signal leaves none behind.
#pragma once

#include <string>

namespace crt::tracer::image_io {

class TemporaryFile {
  public:
    /// Creates a new, empty file beside `target` (same folder, so that the rename is atomic);
    /// on failure, ok() is false and `error` says why.
    TemporaryFile(const std::string& target, std::string& error);
    /// Removes the file unless it was committed.
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    bool ok() const { return fd_ >= 0; }
    const std::string& path() const { return path_; }
    /// Flushes the file to the disk and checks that it holds data, then renames it over the
    /// target; false with the reason (and the temporary removed) if any step fails, in which
    /// case the target is as it was.
    bool commit(std::string& error);

  private:
    void discard();

    std::string target_, path_;
    int fd_ = -1;
    int slot_ = -1; ///< in the table of live temporaries; -1: not listed (table full)
};

/// Unlinks every live temporary file and returns how many there were. Async-signal-safe: for
/// a handler of SIGTERM and the like, or of exit(), which then ends the program.
int removeAllTemporaries() noexcept;

} // namespace crt::tracer::image_io
