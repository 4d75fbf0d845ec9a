// Materials in the scene description: each its own colour, finishes shared where equal.
#include <catch2/catch.hpp>

#include "interpreter.hpp"

#include <set>
#include <string>

using namespace crt::lang;
namespace t = crt::tracer;

namespace {

t::SceneDesc sceneOf(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    Compilation c = compile("m.crt", text, options);
    REQUIRE_FALSE(c.diagnostics.hasErrors());
    REQUIRE(c.scene.has_value());
    return *c.scene;
}

} // namespace

TEST_CASE("materials built in a loop keep their colours and share one finish", "[scene]") {
    t::SceneDesc s = sceneOf(R"(
Scene {
    for i in range(1000) {
        Sphere { center -> vec3(i, 0, 0) radius -> 0.4
                 material -> Material { color -> rgb(i / 1000.0, 0, 0) reflectivity -> 0.25 } }
    }
}
)");
    REQUIRE(s.materials.size() == 1000);
    REQUIRE(s.finishes.size() == 1);
    std::set<double> reds;
    for (const t::MaterialDesc& m : s.materials) {
        reds.insert(m.color.r);
        CHECK(s.finishOf(m).reflectivity == 0.25);
        CHECK(s.finishOf(m).diffuse == 0.75); // its default follows the reflectivity
    }
    CHECK(reds.size() == 1000);
}

TEST_CASE("materials with the default finish store none, different finishes stay apart", "[scene]") {
    t::SceneDesc s = sceneOf(R"(
Scene {
    for i in range(6) {
        Sphere { center -> vec3(i, 0, 0) radius -> 0.4
                 material -> Material { color -> rgb(1, 1, 1) specular -> i % 3 / 2.0 } }
    }
}
)");
    REQUIRE(s.materials.size() == 6);
    for (size_t i = 0; i < s.materials.size(); ++i) {
        CHECK(s.finishOf(s.materials[i]).specular == static_cast<double>(i % 3) / 2.0);
        CHECK(s.finishOf(s.materials[i]).shininess == 3);
        CHECK((s.materials[i].finish < 0) == (i % 3 == 0)); // specular 0 is the default finish
    }
}
