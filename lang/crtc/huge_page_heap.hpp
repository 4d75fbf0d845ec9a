// Backs crtc's heap with transparent huge pages, so building a large scene faults in 2 MB
// pages instead of 4 KB ones.
#pragma once

#include <atomic>
#include <cstddef>
#include <thread>

namespace crt::driver {

/// Sets up the C library's allocator so that every allocation of the process comes from
/// one heap advised to use transparent huge pages. Call first thing in main, before any
/// thread starts. Returns whether the heap was advised; false in sanitizer builds (their
/// allocator is not the C library's) and on kernels without transparent huge pages, where
/// allocation works as before.
bool useHugePageHeap();

/// Faults in, on a thread of its own, up to `bytes` of the heap above what is in use, in
/// steps of one huge page, so that the memory a large script is about to fill is ready when
/// the front end reaches it (a first touch costs about 1 ms per MB on the machines crtc is
/// measured on, half the time of checking a 12 MB script). Does nothing unless
/// useHugePageHeap succeeded. The destructor stops the thread and waits for it.
class HeapPrefault {
public:
    explicit HeapPrefault(size_t bytes);
    ~HeapPrefault();
    HeapPrefault(const HeapPrefault&) = delete;
    HeapPrefault& operator=(const HeapPrefault&) = delete;

private:
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

} // namespace crt::driver
