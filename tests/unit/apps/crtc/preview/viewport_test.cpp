// The preview's side views: where each looks from, and how its pixels map to the scene.
#include "preview/viewport.hpp"

#include "tracer/camera.hpp"

#include <catch2/catch.hpp>

using namespace crt;
using namespace crt::crtc::preview;

namespace {

/// The ray through the middle of pixel (x, y) of the view, as the renderer casts it.
tracer::Ray rayThrough(const scene::SceneDesc& seen, int x, int y) {
    const tracer::Camera camera(seen.camera, seen.settings.width, seen.settings.height, 1);
    return camera.ray(x + 0.5, y + 0.5);
}

} // namespace

TEST_CASE("a side view looks along its axis, its pixels a regular grid of the scene", "[preview]") {
    scene::SceneDesc scene;
    scene.settings.integrator = scene::Integrator::Path;
    scene.settings.shutterClose = 1;
    const Viewport base{ViewportAxis::Top, 2, 3, 8, 240, 180};
    struct Case {
        ViewportAxis axis;
        int across, up; ///< the scene axes right and up the view
        glm::dvec3 looking;
    };
    for (const Case& c : {Case{ViewportAxis::Top, 0, 2, {0, -1, 0}}, Case{ViewportAxis::Front, 0, 1, {0, 0, 1}},
                          Case{ViewportAxis::Side, 2, 1, {-1, 0, 0}}}) {
        Viewport view = base;
        view.axis = c.axis;
        const scene::SceneDesc seen = viewportScene(scene, view);
        INFO("axis " << static_cast<int>(c.axis));
        CHECK(seen.settings.width == 240);
        CHECK(seen.settings.height == 180);
        CHECK(seen.settings.integrator == scene::Integrator::Whitted);
        CHECK_FALSE(seen.settings.shutterIsOpen());
        // 8 units over 240 pixels: pixel (x, y)'s middle is 1/30 of a unit a pixel from the view's
        // middle (2, 3), right and up the view.
        for (auto [x, y] : {std::pair{0, 0}, std::pair{119, 89}, std::pair{239, 179}, std::pair{30, 150}}) {
            const tracer::Ray ray = rayThrough(seen, x, y);
            CHECK(glm::length(glm::normalize(ray.dir) - c.looking) < 1e-12);
            CHECK(ray.origin[c.across] == Approx(2 + (x + 0.5 - 120) / 30).margin(1e-9));
            CHECK(ray.origin[c.up] == Approx(3 - (y + 0.5 - 90) / 30).margin(1e-9));
        }
    }
}

TEST_CASE("side views are named top, front and side", "[preview]") {
    CHECK(viewportAxis("top") == ViewportAxis::Top);
    CHECK(viewportAxis("front") == ViewportAxis::Front);
    CHECK(viewportAxis("side") == ViewportAxis::Side);
    CHECK_FALSE(viewportAxis("below"));
}
