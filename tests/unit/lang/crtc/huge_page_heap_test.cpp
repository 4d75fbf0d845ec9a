// crtc's heap: allocations of every thread land in memory advised for transparent huge pages.
#include "huge_page_heap.hpp"
#include "prefaulter.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <malloc.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <chrono>
#include <thread>
#include <vector>
#include <unistd.h>

namespace {

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) // else unused

/// The VmFlags line of the mapping in /proc/self/smaps that holds `address` ("" if none).
std::string mappingFlags(const void* address) {
    auto where = reinterpret_cast<uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= where && where < end;
        } else if (inside && line.starts_with("VmFlags:")) {
            return line;
        }
    }
    return "";
}

bool kernelHasTransparentHugePages() {
    struct stat info {};
    return stat("/sys/kernel/mm/transparent_hugepage", &info) == 0;
}

#endif

} // namespace

TEST_CASE("crtc's heap is advised for huge pages, for the front end's thread too", "[crtc]") {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    CHECK_FALSE(crt::driver::useHugePageHeap()); // the sanitizer's allocator is left alone
#else
    bool advised = crt::driver::useHugePageHeap();
    REQUIRE(advised == kernelHasTransparentHugePages());
    if (!advised) return;

    // Large blocks (a scene's vectors) would be separate mappings without the setup. Their
    // first bytes may reuse what was free below the heap's old top, so look further in.
    constexpr size_t kLarge = size_t{48} << 20;
    auto large = std::make_unique<char[]>(kLarge);
    CHECK(mappingFlags(large.get() + kLarge / 2).find(" hg") != std::string::npos);
    CHECK(mappingFlags(large.get() + kLarge - 1).find(" hg") != std::string::npos);

    std::unique_ptr<char[]> fromThread;
    std::thread([&] { fromThread = std::make_unique<char[]>(size_t{1} << 20); }).join();
    CHECK(mappingFlags(fromThread.get()).find(" hg") != std::string::npos);
#endif
}

namespace {

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) // else unused

// The share of the pages of [begin, begin + bytes) that are in memory.
double residentShare(const void* begin, size_t bytes) {
    const auto page = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
    const uintptr_t first = reinterpret_cast<uintptr_t>(begin) & ~(page - 1);
    const size_t pages = (reinterpret_cast<uintptr_t>(begin) + bytes - first + page - 1) / page;
    std::vector<unsigned char> flags(pages);
    if (mincore(reinterpret_cast<void*>(first), pages * page, flags.data()) != 0) return 0;
    size_t resident = 0;
    for (unsigned char flag : flags) resident += flag & 1;
    return double(resident) / double(pages);
}

// Whether the kernel can populate memory on request (Linux 5.14 and later); the prefaulter
// does nothing otherwise.
bool kernelPopulates() {
    void* page = mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (page == MAP_FAILED) return false;
    const bool populates = madvise(page, 4096, MADV_POPULATE_WRITE) == 0;
    munmap(page, 4096);
    return populates;
}

// Waits (up to 10 s) until all of the range is in memory, as the prefaulter works in the
// background.
bool becomesResident(const void* begin, size_t bytes) {
    for (int i = 0; i < 1000 && residentShare(begin, bytes) < 1.0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return residentShare(begin, bytes) == 1.0;
}

#endif

} // namespace

TEST_CASE("the prefaulter faults in the heap's free top on its own thread", "[crtc]") {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    crt::driver::Prefaulter nothing; // no huge-page heap: does nothing
    nothing.addHeapTop(size_t{64} << 20);
    CHECK_FALSE(crt::driver::hugePageHeapInUse());
#else
    if (!kernelPopulates()) return; // nothing to test: the prefaulter does nothing
    if (!crt::driver::hugePageHeapInUse() && !crt::driver::useHugePageHeap()) return; // no THP
    // Beyond what this process has touched: the heap's free top, from the allocator's
    // record, past what earlier cases may have used and freed.
    constexpr size_t kAhead = size_t{64} << 20;
    std::unique_ptr<unsigned char[]> used(new unsigned char[size_t{128} << 20]); // not written
    const auto heapEnd = reinterpret_cast<uintptr_t>(sbrk(0));
    const auto* top = reinterpret_cast<const unsigned char*>(heapEnd - mallinfo2().keepcost);
    INFO("free top at " << static_cast<const void*>(top) << ", heap end at "
                        << reinterpret_cast<const void*>(heapEnd));
    REQUIRE(residentShare(top + (size_t{4} << 20), kAhead - (size_t{4} << 20)) < 0.5);
    crt::driver::Prefaulter prefaulter;
    prefaulter.addHeapTop(kAhead);
    CHECK(becomesResident(top + (size_t{4} << 20), kAhead - (size_t{4} << 20)));
    // The allocator then hands that memory out as usual, and its blocks hold what is written.
    std::unique_ptr<unsigned char[]> block(new unsigned char[kAhead / 2]);
    for (size_t i = 0; i < kAhead / 2; i += 4096) block[i] = static_cast<unsigned char>(i >> 12);
    bool intact = true;
    for (size_t i = 0; i < kAhead / 2; i += 4096)
        intact = intact && block[i] == static_cast<unsigned char>(i >> 12);
    CHECK(intact);
#endif
}

TEST_CASE("the prefaulter faults in a block being filled without changing its contents", "[crtc]") {
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    if (!kernelPopulates()) return; // nothing to test: the prefaulter does nothing
    if (!crt::driver::hugePageHeapInUse() && !crt::driver::useHugePageHeap()) return; // no THP
    constexpr size_t kCount = size_t{32} << 20; // 256 MB of doubles, like a reserved scene vector
    std::vector<double> values;
    values.reserve(kCount);
    const double* room = values.data() + (size_t{1} << 20); // past what the writes below reach
    const size_t roomBytes = (kCount - (size_t{1} << 20)) * sizeof(double);
    REQUIRE(residentShare(room, roomBytes) < 0.5);
    crt::driver::Prefaulter prefaulter;
    // The first values are written while the room after them is faulted in.
    for (size_t i = 0; i < 1000; ++i) values.push_back(double(i));
    prefaulter.add(values.data() + values.size(),
                   (values.capacity() - values.size()) * sizeof(double));
    for (size_t i = 1000; i < 2000; ++i) values.push_back(double(i));
    CHECK(becomesResident(room, roomBytes));
    bool intact = true;
    for (size_t i = 0; i < values.size(); ++i) intact = intact && values[i] == double(i);
    CHECK(intact);
    // A range that is not mapped is dropped, not a crash; later ranges still work.
    prefaulter.add(reinterpret_cast<void*>(uintptr_t{4096}), 8192);
    prefaulter.add(values.data(), sizeof(double));
#endif
}
