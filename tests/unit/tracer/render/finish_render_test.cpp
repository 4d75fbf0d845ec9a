// Analytic render tests of the POV-Ray finishes: brilliance, angle-dependent reflection and
// energy conservation. Each checked pixel is recomputed from the documented formula.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr double kTolerance = 1e-4;

/// Renders a floor seen at a slant with a white sky, and checks every floor pixel against
/// `want(cos of the view angle, cos of the light angle)`; returns how many it checked.
template <typename Want> int checkFloor(const ShadingMaterial& floor, bool lit, Want want) {
    const int W = 48, H = 36;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0, 1.5, -4}, {0, 0, 2}, 50));
    m.desc.background.color = scene::Color{1, 1, 1, 1};
    const DVec3 sun = glm::normalize(DVec3(-1, 2, -1));
    if (lit) m.desc.lights.push_back(parallelLight(sun * 10.0));
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    PixelBuffer image = renderOk(m.desc);
    int checked = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            if (!hitPlane(ray, {0, 1, 0}, {0, 0, 0})) continue;
            double cosView = -glm::normalize(ray.dir).y, cosLight = sun.y;
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " cos " << cosView << " got " << got.x);
            CHECK(maxDifference(got, DVec3(want(cosView, cosLight))) < kTolerance);
            ++checked;
        }
    }
    return checked;
}

} // namespace

TEST_CASE("Brilliance makes diffuse light fall as cos^brilliance", "[render][analytic]") {
    ShadingMaterial floor;
    floor.color = scene::Color{1, 1, 1, 1};
    floor.brilliance = 3.5;
    int checked =
        checkFloor(floor, true, [](double, double cosLight) { return std::pow(cosLight, 3.5); });
    CHECK(checked > 300);
}

TEST_CASE("Reflection grows from reflectivitymin facing to reflectivity at grazing",
          "[render][analytic]") {
    ShadingMaterial floor;
    floor.color = scene::Color{0, 0, 0, 1};
    floor.diffuse = 0;
    floor.reflectivityMin = 0.1;
    floor.reflectivity = 0.9;
    floor.reflectionFalloff = 2;
    // The mirror image is the white sky: a pixel is the reflection itself.
    double lowest = 1, highest = 0;
    int checked = checkFloor(floor, false, [&](double cosView, double) {
        double r = 0.1 + 0.8 * std::pow(1 - cosView, 2);
        lowest = std::min(lowest, r);
        highest = std::max(highest, r);
        return r;
    });
    CHECK(checked > 300);
    CHECK(highest - lowest > 0.2); // the view spans angles enough to see the change
}

TEST_CASE("With conserveenergy, diffuse takes what reflection leaves at each point",
          "[render][analytic]") {
    ShadingMaterial floor;
    floor.color = scene::Color{1, 1, 1, 1};
    floor.diffuse = 1;
    floor.conserveEnergy = true;
    floor.reflectivityMin = 0;
    floor.reflectivity = 1;
    floor.transparency = 0;
    int checked = checkFloor(floor, true, [](double cosView, double cosLight) {
        double kr = 1 - cosView;               // falloff 1
        return kr * 1.0 + (1 - kr) * cosLight; // the white sky mirrored, plus diffuse
    });
    CHECK(checked > 300);
}
