// The default number of render threads follows the cores the process may run on.
#include "tracer/renderer.hpp"

#include <catch2/catch.hpp>

#if defined(__linux__)
#include <sched.h>

#include <thread>

namespace {

/// Runs `body` on a new thread whose affinity is the first `count` cores this process may use
/// (a new thread, so the test's own affinity is left alone).
template <class Body> void onCores(int count, Body body) {
    std::thread confined([&] {
        cpu_set_t allowed;
        REQUIRE(sched_getaffinity(0, sizeof allowed, &allowed) == 0);
        cpu_set_t some;
        CPU_ZERO(&some);
        for (int cpu = 0, taken = 0; cpu < CPU_SETSIZE && taken < count; ++cpu)
            if (CPU_ISSET(cpu, &allowed)) CPU_SET(cpu, &some), ++taken;
        REQUIRE(sched_setaffinity(0, sizeof some, &some) == 0);
        body();
    });
    confined.join();
}

} // namespace

TEST_CASE("The default thread count is the number of cores the process may run on", "[render]") {
    cpu_set_t allowed;
    REQUIRE(sched_getaffinity(0, sizeof allowed, &allowed) == 0);
    CHECK(crt::tracer::availableCores() == static_cast<unsigned>(CPU_COUNT(&allowed)));
    onCores(1, [] { CHECK(crt::tracer::availableCores() == 1); });
    if (CPU_COUNT(&allowed) >= 2) onCores(2, [] { CHECK(crt::tracer::availableCores() == 2); });
}
#endif
