// Analytic render tests of fog: what a ray meets is seen by T = exp(−∫density/distance) and
// the fog's colour by 1 − T, on camera rays and on the rays a mirror sends.
//
// The surfaces only glow (black, emission E, no lights), so a pixel is exactly E·T + F·(1 − T)
// with T computed here from the spec camera's ray; ground fog's density is integrated
// numerically, independently of the renderer's closed form.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kWidth = 24, kHeight = 18;
const DVec3 kGlow{0.9, 0.5, 0.1};
const DVec3 kFogColor{0.6, 0.7, 0.8};
const DVec3 kSky{0.1, 0.3, 0.9};

/// A glowing floor at y = 0 seen from above at an angle, the sky above the horizon.
scene::SceneDesc glowingFloor(const scene::FogDesc& fog) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, lookAt({0, 2, -3}, {0, 0.8, 4}, 60));
    m.desc.background.color = {kSky.x, kSky.y, kSky.z, 1};
    ShadingMaterial glow;
    glow.color = scene::Color{0, 0, 0, 1};
    glow.diffuse = 0;
    glow.emission = scene::Color{kGlow.x, kGlow.y, kGlow.z, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(glow)));
    m.desc.fog = fog;
    return m.desc;
}

scene::FogDesc constantFog(double distance, double alpha = 1, double filter = 0) {
    scene::FogDesc fog;
    fog.color = {kFogColor.x, kFogColor.y, kFogColor.z, alpha};
    fog.distance = distance;
    fog.filter = filter;
    return fog;
}

/// ∫ density ds along the ray up to t (kInfinity: for ever), ground fog's density 1 below
/// the altitude and 1/(1 + h²) at h·falloff above it: Simpson's rule over u in [0, 1], with
/// s = t·u, or s = u / (1 − u) for the whole ray (the integrand stays finite as u → 1).
double groundFogDepth(const TestRay& ray, double t, const scene::FogDesc& fog) {
    auto density = [&](double s) {
        const double h = (ray.at(s).y - fog.altitude) / fog.falloff;
        return h <= 0 ? 1.0 : 1 / (1 + h * h);
    };
    const bool whole = t == kInfinity;
    auto integrand = [&](double u) {
        if (!whole) return density(t * u) * t;
        u = std::min(u, 1 - 1e-9);
        return density(u / (1 - u)) / ((1 - u) * (1 - u));
    };
    constexpr int kSteps = 200000;
    const double step = 1.0 / kSteps;
    double sum = integrand(0) + integrand(1);
    for (int i = 1; i < kSteps; ++i) sum += integrand(i * step) * (i % 2 ? 4 : 2);
    return sum * step / 3;
}

/// Checks every pixel against E·T + F·(1 − T) on the floor and S·T + F·(1 − T) in the sky,
/// T from `seen` (the fraction seen through `depth` of fog, kInfinity for the sky).
template <typename Seen>
void checkPixels(const scene::SceneDesc& desc, Seen&& seen, DVec3 filtered = DVec3(1.0)) {
    const PixelBuffer image = renderOk(desc);
    int floor = 0, sky = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const TestRay ray = specCameraRay(desc.camera, kWidth, kHeight, x, y);
            const auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            const double through = seen(ray, t ? *t : kInfinity);
            const DVec3 behind = t ? kGlow : kSky;
            const DVec3 want = behind * filtered * through + kFogColor * (1 - through);
            INFO("pixel " << x << "," << y << (t ? " floor" : " sky") << " seen " << through);
            CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-5);
            ++(t ? floor : sky);
        }
    REQUIRE(floor > 100);
    REQUIRE(sky > 20);
}

} // namespace

TEST_CASE("constant fog shows exp(-d/distance) of what a ray meets and hides the sky",
          "[render][analytic][fog]") {
    for (double distance : {1.0, 4.0, 20.0}) {
        INFO("distance " << distance);
        checkPixels(glowingFloor(constantFog(distance)),
                    [&](const TestRay&, double t) { return std::exp(-t / distance); });
    }
}

TEST_CASE("a fog colour's alpha always lets 1 - alpha through, and filter tints what is seen",
          "[render][analytic][fog]") {
    const double distance = 3;
    checkPixels(glowingFloor(constantFog(distance, 0.4)),
                [&](const TestRay&, double t) { return std::max(std::exp(-t / distance), 0.6); });
    checkPixels(glowingFloor(constantFog(distance, 1, 0.5)),
                [&](const TestRay&, double t) { return std::exp(-t / distance); },
                0.5 + 0.5 * kFogColor);
}

TEST_CASE("ground fog thins as 1/(1 + h^2) above its altitude", "[render][analytic][fog]") {
    scene::FogDesc fog = constantFog(2);
    fog.falloff = 0.7;
    fog.altitude = 0.5;
    // Rays into the sky leave the fog for good: the depth they cross is finite.
    checkPixels(glowingFloor(fog), [&](const TestRay& ray, double t) {
        return std::exp(-groundFogDepth(ray, t, fog) / fog.distance);
    });
}

TEST_CASE("a mirror's reflected ray is fogged along its own length", "[render][analytic][fog]") {
    // Looking straight down at a mirror at y = 0 that shows a glowing ceiling at y = 10.
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 2, 0}, {0, 0, 0}, 40);
    camera.up = {0, 0, 1};
    m.desc = blankScene(9, 9, camera);
    ShadingMaterial mirror;
    mirror.color = scene::Color{0, 0, 0, 1};
    mirror.diffuse = 0;
    mirror.reflectivity = 1;
    ShadingMaterial glow;
    glow.color = scene::Color{0, 0, 0, 1};
    glow.diffuse = 0;
    glow.emission = scene::Color{kGlow.x, kGlow.y, kGlow.z, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(mirror)));
    m.draw(m.plane({0, -1, 0}, {0, 10, 0}, m.material(glow)));
    const double distance = 5;
    m.desc.fog = constantFog(distance);
    const PixelBuffer image = renderOk(m.desc);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) {
            const TestRay ray = specCameraRay(m.desc.camera, 9, 9, x, y);
            const double down = 2 / -ray.dir.y, up = 10 / -ray.dir.y;
            const double seenDown = std::exp(-down / distance), seenUp = std::exp(-up / distance);
            const DVec3 reflected = kGlow * seenUp + kFogColor * (1 - seenUp);
            const DVec3 want = reflected * seenDown + kFogColor * (1 - seenDown);
            INFO("pixel " << x << "," << y);
            CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-5);
        }
}

TEST_CASE("the path integrator fogs each stretch of a path as the Whitted one does", "[render][analytic][fog]") {
    // An orthographic view straight down: every ray, wherever in its pixel, is 3 long.
    scene::SceneDesc desc = glowingFloor(constantFog(2.5));
    desc.camera = lookAt({0, 3, 0}, {0, 0, 0}, 60);
    desc.camera.up = {0, 0, 1};
    desc.camera.projection = scene::Projection::Orthographic;
    desc.camera.width = 4;
    desc.settings.integrator = scene::Integrator::Path;
    desc.settings.samples = 4;
    const PixelBuffer image = renderOk(desc);
    const double seen = std::exp(-3 / 2.5);
    const DVec3 want = kGlow * seen + kFogColor * (1 - seen);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            INFO("pixel " << x << "," << y);
            CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-5);
        }
}
