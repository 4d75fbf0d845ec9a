// A pthread with a large stack for recursive front-end work.
#include "large_stack.hpp"

#include <algorithm>
#include <exception>
#include <iostream>
#include <mutex>
#include <pthread.h>

namespace crt::lang {
namespace {

/// The limit of the work running on this thread; outside runOnLargeStack, what fits the
/// thread's own stack.
thread_local uint32_t currentLimit = 0;

struct Job {
    const std::function<void()>* work;
    std::exception_ptr error;
};

void* runJob(void* argument) {
    auto* job = static_cast<Job*>(argument);
    currentLimit = kMaxNesting;
    try {
        (*job->work)();
    } catch (...) {
        job->error = std::current_exception();
    }
    return nullptr;
}

/// The nesting that fits the calling thread's stack: half of it, since the caller has used
/// some and the walks' frames vary.
uint32_t nestingForOwnStack() {
    size_t stackBytes = size_t{8} << 20;
    pthread_attr_t attributes;
    if (pthread_getattr_np(pthread_self(), &attributes) == 0) {
        void* address = nullptr;
        size_t size = 0;
        if (pthread_attr_getstack(&attributes, &address, &size) == 0 && size > 0) stackBytes = size;
        pthread_attr_destroy(&attributes);
    }
    const size_t levels = stackBytes / 2 / kStackBytesPerNestingLevel;
    return static_cast<uint32_t>(std::clamp<size_t>(levels, 16, kMaxNesting));
}

} // namespace

void runOnLargeStack(const std::function<void()>& work) {
    Job job{&work, nullptr};
    pthread_attr_t attributes;
    pthread_t thread;
    bool started = pthread_attr_init(&attributes) == 0 &&
                   pthread_attr_setstacksize(&attributes, kFrontEndStackBytes) == 0 &&
                   pthread_create(&thread, &attributes, runJob, &job) == 0;
    pthread_attr_destroy(&attributes);
    if (!started) {
        const uint32_t saved = currentLimit;
        currentLimit = nestingForOwnStack();
        static std::once_flag warned;
        std::call_once(warned, [] {
            std::cerr << "warning: cannot reserve a " << (kFrontEndStackBytes >> 20)
                      << " MiB stack for the front end (address-space limit?); scripts may "
                         "nest at most "
                      << currentLimit << " levels deep instead of " << kMaxNesting << "\n";
        });
        try {
            work();
        } catch (...) {
            currentLimit = saved;
            throw;
        }
        currentLimit = saved;
        return;
    }
    pthread_join(thread, nullptr);
    if (job.error) std::rethrow_exception(job.error);
}

uint32_t maxNesting() {
    if (currentLimit == 0) currentLimit = nestingForOwnStack();
    return currentLimit;
}

} // namespace crt::lang
