// A Bump tilts the normal by the slope of its pattern's value: on a floor whose height is a
// gradient along x, every pixel is lit as by the one tilted normal (n − 0.1 · strength · ∇h).
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

TEST_CASE("A Bump of a gradient lights a floor as one tilted plane", "[render][analytic]") {
    const int W = 40, H = 30;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0.3, 2, -3}, {0.3, 0, 0.5}, 40));
    scene::LightDesc sun = parallelLight({2, 3, -1});
    m.desc.lights.push_back(sun);
    scene::TextureDesc gradient = scene::defaultTexture(scene::TextureKind::Gradient);
    gradient.modifiers.push_back({scene::ModifierKind::Scale, DVec3(20.0)}); // no wrap in view
    scene::TextureDesc bump = scene::defaultTexture(scene::TextureKind::Bump);
    bump.pattern = {gradient};
    bump.strength = 2;
    m.desc.textures.push_back(bump);
    ShadingMaterial floor;
    floor.color = scene::Color{1, 1, 1, 1};
    floor.bump = 0;
    m.draw(m.plane({0, 1, 0}, {10, 0, 0}, m.material(floor))); // x > -10: a value in (0, 1)
    PixelBuffer image = renderOk(m.desc);

    // h = x / 20, so ∇h = (0.05, 0, 0); the normal tilts against it.
    DVec3 tilted = glm::normalize(DVec3(0, 1, 0) - 0.1 * 2 * DVec3(0.05, 0, 0));
    double want = std::max(0.0, glm::dot(tilted, glm::normalize(sun.from)));
    double flat = glm::dot(DVec3(0, 1, 0), glm::normalize(sun.from));
    REQUIRE(std::abs(want - flat) > 5e-3); // the tilt is visible in the check
    int checked = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            if (!t || std::abs(ray.at(*t).x) > 9) continue;
            INFO("pixel " << x << "," << y);
            CHECK(std::abs(pixelAt(image, x, y).x - want) < 1e-3);
            ++checked;
        }
    }
    CHECK(checked > 300);
}

TEST_CASE("A Bump of a Checker is flat but for a bevel 0.02 of its units wide before each edge",
          "[render][analytic]") {
    const int W = 120, H = 90;
    const double kScale = 2, kBevel = 0.02 * kScale, kStrength = 0.5;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0.1, 8, -0.1}, {0.1, 1, 0}, 50));
    scene::LightDesc sun = parallelLight({1, 3, -2});
    m.desc.lights.push_back(sun);
    scene::TextureDesc checker = scene::defaultTexture(scene::TextureKind::Checker);
    checker.modifiers.push_back({scene::ModifierKind::Scale, DVec3(kScale)});
    scene::TextureDesc bump = scene::defaultTexture(scene::TextureKind::Bump);
    bump.pattern = {checker};
    bump.strength = kStrength;
    m.desc.textures.push_back(bump);
    ShadingMaterial floor;
    floor.color = scene::Color{1, 1, 1, 1};
    floor.bump = 0;
    // The floor at y = 1: half a cell up, clear of the checker's edges along y.
    m.draw(m.plane({0, 1, 0}, {0, 1, 0}, m.material(floor)));
    PixelBuffer image = renderOk(m.desc);

    DVec3 light = glm::normalize(sun.from);
    auto litBy = [&](DVec3 n) { return std::max(0.0, glm::dot(glm::normalize(n), light)); };
    // Where a point is in its cell along an axis, in cells: 0 at the low edge, 1 at the high.
    auto inCell = [&](double v) { return v / kScale - std::floor(v / kScale); };
    int flat = 0, bevelled = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            auto t = hitPlane(ray, {0, 1, 0}, {0, 1, 0});
            if (!t) continue;
            DVec3 p = ray.at(*t);
            double toEdgeX = (1 - inCell(p.x)) * kScale, toEdgeZ = (1 - inCell(p.z)) * kScale;
            double fromEdgeX = inCell(p.x) * kScale, fromEdgeZ = inCell(p.z) * kScale;
            bool clearZ = toEdgeZ > 2 * kBevel && fromEdgeZ > 0.01;
            INFO("pixel " << x << "," << y << " at " << p.x << "," << p.z);
            if (toEdgeX > 2 * kBevel && fromEdgeX > 0.01 && clearZ) {
                CHECK(std::abs(pixelAt(image, x, y).x - litBy({0, 1, 0})) < 1e-3);
                ++flat;
            } else if (toEdgeX > 0.2 * kBevel && toEdgeX < 0.8 * kBevel && clearZ) {
                // The next cell along x has the other height: the slope is ±1 over the bevel.
                long cell = static_cast<long>(std::floor(p.x / kScale) + std::floor(p.z / kScale) +
                                              std::floor(p.y / kScale));
                double rise = (cell & 1) ? -1 : 1;
                DVec3 n(-0.1 * kStrength * rise / kBevel, 1, 0);
                CHECK(std::abs(pixelAt(image, x, y).x - litBy(n)) < 1e-3);
                ++bevelled;
            }
        }
    }
    CHECK(flat > 3000);
    CHECK(bevelled > 20);
    REQUIRE(std::abs(litBy({-0.1 * kStrength / kBevel, 1, 0}) - litBy({0, 1, 0})) > 0.1);
}
