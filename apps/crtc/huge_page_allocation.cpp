// Large allocations in transparent huge pages.
//
// Every page a process touches first costs a fault. A big scene's arrays (its primitives,
// the BVH's build items and nodes, a mesh's vertices) run to tens or hundreds of megabytes,
// and in 4 KiB pages their faults can take longer than the build that fills them; in 2 MiB
// pages they are 512 times fewer. Linux gives huge pages unasked only where transparent huge
// pages are set to `always`; where they are set to `madvise` (a common default) memory must
// ask for them, which is what this replacement of operator new does for allocations of
// 2 MiB and more: aligned to 2 MiB, their size rounded up to it, so no huge page is shared
// with other data. The rounding costs at most one huge page per such allocation. The
// default operator delete frees them, as it frees everything from malloc.
//
// Not under AddressSanitizer, whose own operator new and delete check that they pair up.
#include <cstdint>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

#if !defined(__SANITIZE_ADDRESS__) && defined(MADV_HUGEPAGE)

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

void* inHugePages(std::size_t size) {
    if (size > SIZE_MAX - kHugePage) return nullptr;
    const std::size_t rounded = (size + kHugePage - 1) & ~(kHugePage - 1);
    void* memory = std::aligned_alloc(kHugePage, rounded);
    // A kernel without transparent huge pages refuses the advice; the memory is as good.
    if (memory) madvise(memory, rounded, MADV_HUGEPAGE);
    return memory;
}

} // namespace

void* operator new(std::size_t size) {
    for (;;) {
        void* memory = size >= kHugePage ? inHugePages(size) : std::malloc(size == 0 ? 1 : size);
        if (memory) return memory;
        std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

#endif
