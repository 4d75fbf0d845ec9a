// Runs one piece of work on several threads at once, the calling thread among them.
#pragma once

#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace crt::tracer {

/// Calls worker(i) for every i in [0, count), each on a thread of its own (i = 0 on the
/// calling thread, and any call no thread can be had for), and returns once every call has.
/// An exception thrown by a call (std::bad_alloc, most likely) is thrown again here, once
/// every call has ended: on a thread of its own it would end the program.
template <class Worker>
void runOnThreads(size_t count, Worker&& worker) {
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto call = [&](size_t i) {
        try {
            worker(i);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    std::vector<size_t> leftOver;
    threads.reserve(count);
    leftOver.reserve(count);
    for (size_t i = 1; i < count; ++i) {
        try {
            threads.emplace_back(call, i);
        } catch (const std::system_error&) {
            leftOver.push_back(i);
        }
    }
    call(0);
    for (size_t i : leftOver) call(i);
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
}

} // namespace crt::tracer
