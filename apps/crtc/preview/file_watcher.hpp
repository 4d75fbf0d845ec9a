// Watches the files a script was built from (the script, its includes, its images and
// meshes) by polling their modification time, size and inode: a save of any kind (in place,
// or a new file renamed over the old) is seen within one poll.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace crt::crtc::preview {

class FileWatcher {
public:
    /// `onChange` is called from the watcher's thread when a watched file changed, appeared
    /// or disappeared since watch() was given it, and then stayed as it is for one interval.
    FileWatcher(std::chrono::milliseconds interval, std::function<void()> onChange);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    /// Watches `paths` from now on, as they are now, instead of the files watched before.
    void watch(const std::vector<std::string>& paths);

private:
    /// What a file looks like from outside; equal stamps: unchanged.
    struct Stamp {
        bool exists = false;
        long long modified = 0; ///< nanoseconds
        long long size = 0;
        unsigned long long inode = 0;
        bool operator==(const Stamp&) const = default;
    };
    static Stamp stampOf(const std::string& path);
    void run();

    std::chrono::milliseconds interval_;
    std::function<void()> onChange_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<std::pair<std::string, Stamp>> files_;
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace crt::crtc::preview
