// Loops reserve room in the scene description once, after their first iteration, so that
// the entity and material vectors are not regrown (copied and faulted in again) while they run.
#include <catch2/catch.hpp>

#include "interpreter.hpp"

#include <string>

using namespace crt::lang;

namespace {

Compilation compileScript(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    Compilation c = compile("g.crt", text, options);
    REQUIRE_FALSE(c.diagnostics.hasErrors());
    REQUIRE(c.scene.has_value());
    return c;
}

} // namespace

TEST_CASE("nested loops size the scene's vectors to what they build", "[scene]") {
    Compilation c = compileScript(R"(
Scene {
    for i in range(40) {
        for j in range(125) {
            Sphere { center -> vec3(i, j, 0) radius -> 0.4
                     material -> Material { color -> rgb(i / 40.0, j / 125.0, 0.5) } }
        }
    }
}
)");
    const auto& scene = *c.scene;
    REQUIRE(scene.entities.size() == 5000);
    REQUIRE(scene.materials.size() == 5000);
    // Grown by doubling or eightfold instead, they would hold up to 8 times more.
    CHECK(scene.entities.capacity() == 5000);
    CHECK(scene.materials.capacity() == 5000);
}

TEST_CASE("a loop over a list reserves too, and a loop that builds nothing reserves nothing", "[scene]") {
    Compilation c = compileScript(R"(
xs = range(300)
total = 0
for i in range(100000) { total = total + i }
Scene {
    for x in xs { Sphere { center -> vec3(x, 0, 0) radius -> 0.4 } }
}
)");
    const auto& scene = *c.scene;
    REQUIRE(scene.entities.size() == 300);
    CHECK(scene.entities.capacity() == 300); // not 100,000: the first loop added nothing
}

TEST_CASE("under a raised entity limit, a loop's reservation stays bounded and evaluation goes on", "[scene]") {
    EvalOptions options;
    options.checkFiles = false;
    options.limits.maxEntities = 100'000'000'000; // raised: 10^9 entities would be ~112 GB
    Compilation c = compile("g.crt", R"(
Scene {
    for i in range(1000000000) {
        if (i == 0) { Sphere { center -> vec3(0, 0, 0) radius -> 1.0 } }
        if (i == 2) { x = 1 / 0 }
    }
}
)", options);
    REQUIRE(c.diagnostics.hasErrors());
    CHECK(c.diagnostics.items().front().message == "integer division by zero");
}
