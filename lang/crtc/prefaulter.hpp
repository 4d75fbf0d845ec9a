// Faults memory in on a second core before the front end fills it.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>

namespace crt::driver {

/// A thread that faults in (MADV_POPULATE_WRITE) ranges of memory it is given, one huge page
/// at a time, so that they are ready when the front end writes them. On the machines crtc is
/// measured on, a first touch costs about 1 ms per MB even in 2 MB pages: about half the time
/// of building a scene of 100,000 spheres. Populating only simulates write faults, so a range
/// that is being written meanwhile, or was freed since, is left as it is. Works only with
/// crtc's huge-page heap (useHugePageHeap); otherwise every call does nothing. The thread
/// starts with the first range; the destructor stops it and waits for it.
class Prefaulter {
public:
    Prefaulter() = default;
    ~Prefaulter();
    Prefaulter(const Prefaulter&) = delete;
    Prefaulter& operator=(const Prefaulter&) = delete;

    /// Queues [begin, begin + bytes) (whole pages inside it). Thread-safe.
    void add(void* begin, std::size_t bytes);
    /// Queues up to `bytes` of the heap's free top, where the next blocks will be carved.
    void addHeapTop(std::size_t bytes);

private:
    void run();

    struct Range {
        std::uintptr_t begin, end;
    };
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Range> queue_;
    bool stop_ = false;
    std::thread thread_;
};

} // namespace crt::driver
