// The original CRT's scripts (../shared/conformance) check with no diagnostics, and their
// evaluated scenes have the objects the scripts describe. Skipped (exit 77) when the
// folder is absent.
// Catch2's prebuilt main runs the cases; the listener is what skips the run (compiling a main
// of our own would compile all of Catch2 in this file).
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include "interpreter.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace crt::lang;
namespace t = crt::scene;

namespace {

fs::path conformanceDir;

// Ends the run with 77, which CTest reports as skipped, when the scripts are not there.
struct ConformanceDirCheck : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testRunStarting(const Catch::TestRunInfo&) override {
        const char* dir = std::getenv("CRT_CONFORMANCE_DIR");
        conformanceDir = dir ? dir : "";
        if (conformanceDir.empty() || !fs::exists(conformanceDir / "demo01.crt")) {
            std::cout << "skipped: the conformance scripts are not at '" << conformanceDir.string()
                      << "' (set CRT_CONFORMANCE_DIR)" << std::endl;
            std::exit(77);
        }
    }
};
CATCH_REGISTER_LISTENER(ConformanceDirCheck)

Compilation check(const std::string& name, int frame = 0, int frames = 1) {
    EvalOptions options;
    options.frame = frame;
    options.frameCount = frames;
    Compilation c = compileFile((conformanceDir / name).string(), options);
    INFO(name << " frame " << frame);
    CHECK(c.diagnostics.items().empty());
    REQUIRE(c.scene.has_value());
    return c;
}

template <typename T> int count(const t::SceneDesc& scene) {
    int n = 0;
    for (const t::EntityDesc& e : scene.entities) n += std::holds_alternative<T>(e.shape) ? 1 : 0;
    return n;
}

} // namespace

TEST_CASE("demo01: the mirror room") {
    Compilation c = check("demo01.crt");
    const t::SceneDesc& s = *c.scene;
    CHECK(s.drawn.size() == 7);
    CHECK(count<t::PlaneShape>(s) == 6);
    CHECK(count<t::SphereShape>(s) == 1);
    CHECK(s.camera.position == glm::dvec3(0.5, 0.5, -0.3));
    CHECK(s.camera.pointing == glm::dvec3(0.0, 0.5, 1.0));
    CHECK(s.camera.fov == 90.0);
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].kind == t::LightKind::Point);
    CHECK(s.lights[0].falloff == 70.0);
    CHECK(s.lights[0].origin == glm::dvec3(1.0, 2.0, -1.0));
    CHECK(s.settings.recursionDepth == 10);
    CHECK(s.settings.supersampling == 4);
    // The two mirror walls share one material; reflectivity 0.93 leaves diffuse 0.07.
    const t::EntityDesc& back = s.entities[static_cast<size_t>(s.drawn[3])];
    const t::EntityDesc& front = s.entities[static_cast<size_t>(s.drawn[4])];
    CHECK(back.material == front.material);
    const t::FinishDesc& mirror = s.finishOf(s.materials[static_cast<size_t>(back.material)]);
    CHECK(mirror.reflectivity == Approx(0.93));
    CHECK(mirror.diffuse == Approx(0.07));
    CHECK(s.background.kind == t::BackgroundKind::Solid);
    CHECK(s.background.color.r == 1.0);
}

TEST_CASE("demo02: carved box, coloured spheres, depth of field, panorama") {
    Compilation c = check("demo02.crt");
    const t::SceneDesc& s = *c.scene;
    REQUIRE(s.drawn.size() == 3);
    // carvedBox = box - boxMask
    const auto* carved = std::get_if<t::CsgNode>(&s.entities[static_cast<size_t>(s.drawn[0])].shape);
    REQUIRE(carved);
    CHECK(carved->op == t::CsgOp::Difference);
    CHECK(std::holds_alternative<t::BoxShape>(s.entities[static_cast<size_t>(carved->left)].shape));
    const auto* mask = std::get_if<t::SphereShape>(&s.entities[static_cast<size_t>(carved->right)].shape);
    REQUIRE(mask);
    CHECK(mask->radius == 0.68);
    // coloredSpheres = sph1 + ... + sph7: a left-leaning chain of six unions.
    int unions = 0;
    int32_t node = s.drawn[1];
    while (const auto* u = std::get_if<t::CsgNode>(&s.entities[static_cast<size_t>(node)].shape)) {
        CHECK(u->op == t::CsgOp::Union);
        ++unions;
        node = u->left;
    }
    CHECK(unions == 6);
    CHECK(count<t::SphereShape>(s) == 8);
    CHECK(s.lights.size() == 4);
    CHECK(s.lights[3].kind == t::LightKind::Parallel);
    CHECK(s.camera.apertureShape == t::ApertureShape::Polygon);
    CHECK(s.camera.apertureBlades == 5);
    CHECK(s.camera.aperture == 50.0);
    CHECK(s.camera.focalDistance == Approx(3.7));
    CHECK(s.camera.fov == Approx(75.0));
    CHECK(s.settings.dofSamples == 50);
    CHECK(s.background.kind == t::BackgroundKind::Image);
    CHECK(s.background.angle == 3.4);
    CHECK(fs::equivalent(s.background.resolvedImage, conformanceDir / "images/panorama/sky.jpg"));
}

TEST_CASE("demo02: rand() is deterministic and in range") {
    Compilation a = check("demo02.crt");
    Compilation b = check("demo02.crt");
    REQUIRE(a.scene->materials.size() == b.scene->materials.size());
    int randomColours = 0;
    for (size_t i = 0; i < a.scene->materials.size(); ++i) {
        const t::Color& x = a.scene->materials[i].color;
        CHECK(x.r == b.scene->materials[i].color.r);
        if (a.scene->finishOf(a.scene->materials[i]).reflectivity != 0.5) continue; // the seven spheres
        ++randomColours;
        for (double channel : {x.r, x.g, x.b}) CHECK((channel >= 0.0 && channel < 1.0));
    }
    CHECK(randomColours == 7);
}

TEST_CASE("animations: every frame checks, and t moves things") {
    Compilation first = check("demo01Animation.crt", 0, 20);
    Compilation last = check("demo01Animation.crt", 19, 20);
    CHECK(first.scene->drawn.size() == 10);
    CHECK(first.scene->camera.pointing == glm::dvec3(0.0, 0.5, 1.0));
    CHECK(last.scene->camera.pointing.x == Approx(0.19));
    CHECK(last.scene->lights[0].origin.x == Approx(1.0 - 1.9));
    for (int frame = 0; frame < 60; frame += 7) {
        Compilation c = check("demo02Animation.crt", frame, 60);
        CHECK(c.scene->drawn.size() == 3);
    }
}
