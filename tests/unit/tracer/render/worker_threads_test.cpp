// runOnThreads: every call runs, and a call's exception reaches the caller once all have ended.
#include "tracer/worker_threads.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <new>

using namespace crt::tracer;

TEST_CASE("runOnThreads makes every call, on the caller's thread too", "[threads]") {
    std::atomic<int> calls{0}, sum{0};
    runOnThreads(5, [&](size_t i) {
        calls.fetch_add(1);
        sum.fetch_add(static_cast<int>(i));
    });
    CHECK(calls.load() == 5);
    CHECK(sum.load() == 0 + 1 + 2 + 3 + 4);
}

TEST_CASE("runOnThreads throws a call's exception again once every call has ended", "[threads]") {
    for (size_t throwing : {size_t{0}, size_t{2}}) {
        INFO("call " << throwing << " throws");
        std::atomic<int> finished{0};
        CHECK_THROWS_AS(runOnThreads(4,
                                     [&](size_t i) {
                                         if (i == throwing) throw std::bad_alloc();
                                         finished.fetch_add(1);
                                     }),
                        std::bad_alloc);
        CHECK(finished.load() == 3);
    }
}
