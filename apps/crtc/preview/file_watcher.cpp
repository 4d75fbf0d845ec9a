// Polling file watcher (see file_watcher.hpp).
#include "preview/file_watcher.hpp"

#include <sys/stat.h>

namespace crt::crtc::preview {

FileWatcher::FileWatcher(std::chrono::milliseconds interval, std::function<void()> onChange)
    : interval_(interval), onChange_(std::move(onChange)), thread_([this] { run(); }) {}

FileWatcher::~FileWatcher() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void FileWatcher::watch(const std::vector<std::string>& paths) {
    std::vector<std::pair<std::string, Stamp>> files;
    for (const std::string& path : paths) files.emplace_back(path, stampOf(path));
    std::lock_guard lock(mutex_);
    files_ = std::move(files);
}

FileWatcher::Stamp FileWatcher::stampOf(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return {};
    return {true, static_cast<long long>(info.st_mtim.tv_sec) * 1'000'000'000 + info.st_mtim.tv_nsec,
            static_cast<long long>(info.st_size), static_cast<unsigned long long>(info.st_ino)};
}

void FileWatcher::run() {
    std::unique_lock lock(mutex_);
    bool settling = false; // a change was seen at the last poll
    while (!wake_.wait_for(lock, interval_, [this] { return stopping_; })) {
        bool changed = false;
        for (auto& [path, stamp] : files_) {
            Stamp now = stampOf(path);
            if (now != stamp) {
                stamp = now;
                changed = true;
            }
        }
        // A save is often a truncation, then writes: report it once a poll finds the files
        // as the previous one left them, so that the half-written script is not evaluated.
        if (changed || !settling) {
            settling = changed;
            continue;
        }
        settling = false;
        // Called unlocked: the callback may well call watch().
        lock.unlock();
        onChange_();
        lock.lock();
    }
}

} // namespace crt::crtc::preview
