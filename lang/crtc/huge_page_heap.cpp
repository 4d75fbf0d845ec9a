// Transparent huge pages for crtc's heap (see huge_page_heap.hpp).
//
// Why: on the virtual machines crtc is measured on, a first touch of a 4 KB page costs
// 3 to 15 µs, so the 33 MB description of a 100,000-sphere scene spent more time in page
// faults than in building it. A 2 MB page is one fault for 512 of them.
//
// How, with documented mallopt(3) settings only: all threads allocate from the main arena
// (the front end runs on a thread of its own), nothing is served by a separate mmap, and
// the heap is extended once, by a large pad, then never trimmed; that one region is then
// advised with MADV_HUGEPAGE. The pad is address space only: pages not touched cost nothing.
#include "huge_page_heap.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

namespace crt::driver {

namespace {

/// Whether useHugePageHeap set the heap up.
bool heapAdvised = false;

/// mallopt(3)'s defaults for what useHugePageHeap changes.
[[maybe_unused]] void restoreAllocatorDefaults() { // unused in sanitizer builds
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    mallopt(M_ARENA_MAX, static_cast<int>(8 * std::max(cores, 1L))); // the 64-bit default
    mallopt(M_MMAP_MAX, 65536);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
    mallopt(M_TOP_PAD, 128 * 1024);
}

} // namespace

bool useHugePageHeap() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    return false;
#else
    constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
    constexpr size_t kPad = size_t{1} << 30;
    if (mallopt(M_ARENA_MAX, 1) == 0 || mallopt(M_MMAP_MAX, 0) == 0 ||
        mallopt(M_TRIM_THRESHOLD, INT32_MAX) == 0 || mallopt(M_TOP_PAD, static_cast<int>(kPad)) == 0) {
        restoreAllocatorDefaults();
        return false;
    }
    auto before = reinterpret_cast<uintptr_t>(sbrk(0));
    uintptr_t heapStart = before - mallinfo2().arena; // one arena so far: the heap below the break
    // Larger than what is left of the heap's top: the allocator extends the heap by it and the
    // pad. Through a volatile pointer, or the compiler removes the pair.
    void* volatile block = std::malloc(size_t{1} << 20);
    std::free(block);
    auto after = reinterpret_cast<uintptr_t>(sbrk(0));
    // From the huge page holding the old top (memory freed below it joins what is added),
    // unless that page begins before the heap.
    uintptr_t begin = before & ~(kHugePage - 1);
    if (begin < heapStart) begin += kHugePage;
    uintptr_t end = after & ~(kHugePage - 1);
    if (end > begin && madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0) {
        heapAdvised = true;
        return true;
    }
    // No such region (the break could not move by the pad, as under strict overcommit) or no
    // transparent huge pages: the settings would only cost, so the allocator gets its own back.
    restoreAllocatorDefaults();
    return false;
#endif
}

bool hugePageHeapInUse() {
    return heapAdvised;
}

} // namespace crt::driver
