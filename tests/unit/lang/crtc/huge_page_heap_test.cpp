// crtc's heap: allocations of every thread land in memory advised for transparent huge pages.
#include "huge_page_heap.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <thread>

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
