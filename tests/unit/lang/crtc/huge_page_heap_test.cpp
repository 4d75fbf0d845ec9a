// crtc's heap: allocations of every thread land in memory advised for transparent huge pages.
#include "huge_page_heap.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <chrono>
#include <thread>
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

TEST_CASE("HeapPrefault faults in the free top of the heap on its own thread", "[crtc]") {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    crt::driver::HeapPrefault nothing(size_t{64} << 20); // no advised heap: does nothing
    SUCCEED();
#else
    if (!crt::driver::useHugePageHeap()) return; // no transparent huge pages: nothing to fault in
    auto residentBytes = [] {
        std::ifstream statm("/proc/self/statm");
        size_t pages = 0, resident = 0;
        statm >> pages >> resident;
        return resident * static_cast<size_t>(sysconf(_SC_PAGESIZE));
    };
    constexpr size_t kAhead = size_t{64} << 20;
    const size_t before = residentBytes();
    {
        crt::driver::HeapPrefault prefault(kAhead);
        // The thread works in the background: wait (up to 10 s) for the memory to be there.
        for (int i = 0; i < 1000 && residentBytes() < before + kAhead * 3 / 4; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    CHECK(residentBytes() >= before + kAhead * 3 / 4);
    // The allocator then hands out that memory as usual, and its blocks hold what is written.
    auto block = std::make_unique<unsigned char[]>(kAhead / 2);
    for (size_t i = 0; i < kAhead / 2; i += 4096) block[i] = static_cast<unsigned char>(i >> 12);
    bool intact = true;
    for (size_t i = 0; i < kAhead / 2; i += 4096)
        intact = intact && block[i] == static_cast<unsigned char>(i >> 12);
    CHECK(intact);
#endif
}
