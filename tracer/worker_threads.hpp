// Runs one piece of work on several threads at once, the calling thread among them.
#pragma once

#include <cstddef>
#include <thread>
#include <vector>

namespace crt::tracer {

/// Calls worker(i) for every i in [0, count), each on a thread of its own (i = 0 on the
/// calling thread), and returns once every call has.
template <class Worker>
void runOnThreads(size_t count, Worker&& worker) {
    std::vector<std::thread> threads;
    for (size_t i = 1; i < count; ++i) threads.emplace_back(worker, i);
    worker(size_t{0});
    for (std::thread& t : threads) t.join();
}

} // namespace crt::tracer
