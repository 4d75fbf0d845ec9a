// The prefaulting thread (see prefaulter.hpp).
#include "prefaulter.hpp"

#include "huge_page_heap.hpp"

#include <algorithm>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

namespace crt::driver {

namespace {

constexpr std::uintptr_t kPage = 4096;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

} // namespace

Prefaulter::~Prefaulter() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    if (thread_.joinable()) thread_.join();
}

void Prefaulter::add(void* begin, std::size_t bytes) {
#if defined(MADV_POPULATE_WRITE)
    if (!hugePageHeapInUse() || bytes == 0) return;
    const auto address = reinterpret_cast<std::uintptr_t>(begin);
    const Range range{(address + kPage - 1) & ~(kPage - 1), (address + bytes) & ~(kPage - 1)};
    if (range.end <= range.begin) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stop_) return;
        queue_.push_back(range);
        if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    }
    wake_.notify_one();
#else
    (void)begin;
    (void)bytes;
#endif
}

void Prefaulter::addHeapTop(std::size_t bytes) {
    if (!hugePageHeapInUse()) return;
    // The allocator carves new blocks from the bottom of the free top chunk, which ends at
    // the break.
    const auto heapEnd = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t top = heapEnd - mallinfo2().keepcost;
    add(reinterpret_cast<void*>(top), std::min<std::uintptr_t>(bytes, heapEnd - top));
}

void Prefaulter::run() {
#if defined(MADV_POPULATE_WRITE)
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (stop_) return;
        Range range = queue_.front();
        queue_.pop_front();
        lock.unlock();
        // Huge page by huge page, so that a stop is seen soon. A failure (the range was
        // unmapped, or an older kernel) drops the rest of the range.
        for (std::uintptr_t at = range.begin; at < range.end;) {
            const std::uintptr_t next = std::min(range.end, (at + kHugePage) & ~(kHugePage - 1));
            if (madvise(reinterpret_cast<void*>(at), next - at, MADV_POPULATE_WRITE) != 0) break;
            at = next;
            std::lock_guard<std::mutex> check(mutex_);
            if (stop_) return;
        }
        lock.lock();
    }
#endif
}

} // namespace crt::driver
