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
