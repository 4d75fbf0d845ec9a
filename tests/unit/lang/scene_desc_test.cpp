// The scene description the interpreter builds: materials (each its own color, finishes
// shared where equal) and what loops add to it.
#include <catch2/catch.hpp>

#include "interpreter.hpp"
#include "scene/instancing.hpp"

#include <set>
#include <string>

using namespace crt::lang;
namespace t = crt::scene;

namespace {

Compilation compileScript(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    Compilation c = compile("s.crt", text, options);
    REQUIRE_FALSE(c.diagnostics.hasErrors());
    REQUIRE(c.scene.has_value());
    return c;
}

} // namespace

TEST_CASE("materials built in a loop keep their colors and share one finish", "[scene]") {
    Compilation c = compileScript(R"(
Scene {
    for i in range(1000) {
        Sphere { center -> vec3(i, 0, 0) radius -> 0.4
                 material -> Material { color -> rgb(i / 1000.0, 0, 0) reflectivity -> 0.25 } }
    }
}
)");
    const t::SceneDesc& s = *c.scene;
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
    Compilation c = compileScript(R"(
Scene {
    for i in range(6) {
        Sphere { center -> vec3(i, 0, 0) radius -> 0.4
                 material -> Material { color -> rgb(1, 1, 1) specular -> i % 3 / 2.0 } }
    }
}
)");
    const t::SceneDesc& s = *c.scene;
    REQUIRE(s.materials.size() == 6);
    for (size_t i = 0; i < s.materials.size(); ++i) {
        CHECK(s.finishOf(s.materials[i]).specular == static_cast<double>(i % 3) / 2.0);
        CHECK(s.finishOf(s.materials[i]).shininess == 3);
        CHECK((s.materials[i].finish < 0) == (i % 3 == 0)); // specular 0 is the default finish
    }
}

TEST_CASE("nested loops add every entity and material they build", "[scene]") {
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
}

TEST_CASE("a loop over a list draws each item; a loop that builds nothing adds nothing", "[scene]") {
    Compilation c = compileScript(R"(
xs = range(300)
total = 0
for i in range(100000) { total = total + i }
Scene {
    for x in xs { Sphere { center -> vec3(x, 0, 0) radius -> 0.4 } }
}
)");
    const auto& scene = *c.scene;
    CHECK(scene.entities.size() == 300);
}

TEST_CASE("under a raised entity limit, a long loop that builds once evaluates on", "[scene]") {
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

TEST_CASE("the 2015 aperture shape \"uniform\" builds the same camera as \"circle\"", "[scene]") {
    auto camera = [](const std::string& shape) {
        Compilation c = compileScript(
            "Settings { camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) "
            "aperture -> 2 apertureshape -> \"" + shape + "\" } dofsamples -> 4 }\n"
            "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }\n");
        return c.scene->camera;
    };
    t::CameraDesc circle = camera("circle");
    for (const std::string shape : {"uniform", "UNIFORM", "Uniform"}) {
        t::CameraDesc uniform = camera(shape);
        CHECK(uniform.apertureShape == t::ApertureShape::Circle);
        CHECK(uniform.apertureShape == circle.apertureShape);
        CHECK(uniform.apertureBlades == circle.apertureBlades);
        CHECK(uniform.aperture == circle.aperture);
    }
}

namespace {

bool warnsNoLights(const std::string& text) {
    Compilation c = compileScript(text);
    for (const Diagnostic& d : c.diagnostics.items())
        if (d.warning == WarningKind::NoLights) return true;
    return false;
}

} // namespace

TEST_CASE("a scene warns of no lights only when nothing lights it", "[scene]") {
    const std::string ball = "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 @ } }\n";
    auto with = [&](const std::string& settings, const std::string& attributes) {
        std::string text = settings + ball;
        return text.replace(text.find('@'), 1, attributes);
    };
    CHECK(warnsNoLights(with("", "")));
    CHECK(warnsNoLights(with("Settings { width -> 100 }\n", "")));
    CHECK_FALSE(warnsNoLights(with(
        "Settings { lights -> [PointLight { origin -> vec3(0, 5, 0) color -> rgb(1, 1, 1) }] }\n",
        "")));
    CHECK_FALSE(warnsNoLights(with("Settings { ambient -> rgb(0.2, 0.2, 0.2) }\n", "")));
    CHECK_FALSE(warnsNoLights(with("", "material -> Material { emission -> rgb(1, 0.5, 0) }")));
    // A glowing material only counts where it is drawn.
    CHECK(warnsNoLights("glow = Material { emission -> rgb(1, 1, 1) }\n" + with("", "")));
    // Nothing drawn: the empty scene says so instead.
    CHECK_FALSE(warnsNoLights("x = 1\n"));
}

TEST_CASE("the description keeps the count of what it stores, made once it is finished", "[scene]") {
    // A group of 20 spheres drawn three times (stored once, each drawing an instance), then
    // a sphere of its own: the count the renderer would make of the finished description.
    Compilation c = compileScript(R"(
row = Macro () {
  for i in range(20) { Sphere { center -> vec3(i, 0, 0) radius -> 0.4 } }
}
r = row()
Scene {
  r
  r <translate vec3(0, 1, 0)>
  r <translate vec3(0, 2, 0)>
  Sphere { center -> vec3(0, 5, 0) radius -> 1 }
}
)");
    const t::SceneDesc& s = *c.scene;
    REQUIRE(s.storage);
    const t::SceneStorage counted = t::storageOf(s);
    CHECK(s.storage->instances == 3);
    CHECK(s.storage->stored() == 20 + 3 + 1);
    CHECK(s.storage->storedAfter == counted.storedAfter);
    CHECK(s.storage->expansion == counted.expansion);
    CHECK(s.storage->instanced == counted.instanced);
    CHECK(s.storage->copied == counted.copied);
}
