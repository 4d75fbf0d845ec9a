// crtc's operator new: allocations of 2 MiB and more start on a 2 MiB boundary and are
// marked for transparent huge pages (VmFlags "hg" in /proc/self/smaps).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

// Under AddressSanitizer its own operator new is used, and this test is not built.
#if !defined(__SANITIZE_ADDRESS__)

namespace {

constexpr uintptr_t kHugePage = uintptr_t{2} << 20;

/// The VmFlags of the mapping holding `address`, from /proc/self/smaps ("" if none is found).
std::string mappingFlags(const void* address) {
    const auto at = reinterpret_cast<uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> lo >> dash >> hi && dash == '-') {
            inside = lo <= at && at < hi;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

bool hasFlag(const std::string& flags, const std::string& flag) {
    return (flags + " ").find(" " + flag + " ") != std::string::npos;
}

} // namespace

TEST_CASE("a large allocation is aligned to a huge page and advised into huge pages", "[huge_pages]") {
    if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled")) {
        WARN("not checked: this kernel has no transparent huge pages");
        return;
    }
    for (size_t size : {kHugePage, kHugePage + 1, 9 * kHugePage + 12345}) {
        auto block = std::make_unique<char[]>(size);
        block[size - 1] = 1; // usable to its end
        CHECK(reinterpret_cast<uintptr_t>(block.get()) % kHugePage == 0);
        CHECK(hasFlag(mappingFlags(block.get()), "hg"));
    }
    std::vector<int32_t> grown;
    for (int32_t i = 0; i < (1 << 20); ++i) grown.push_back(i); // 4 MiB, reallocated on the way
    CHECK(reinterpret_cast<uintptr_t>(grown.data()) % kHugePage == 0);
    CHECK(hasFlag(mappingFlags(grown.data()), "hg"));
    CHECK(grown[123456] == 123456);
}
#endif
