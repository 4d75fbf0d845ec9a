// Analytic render tests of the cylinder light (a segment that emits, total intensity `color`
// spread along it, sampled in `shadowsamples` strata along its length).
//
// A white diffuse floor lit only by the light: a pixel is (I/L)·∫ (n·l) ds over the part of the
// segment the floor point sees (falloff and attenuation multiplying inside the integral),
// which for a straight segment has a closed form.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 33;
constexpr double kIntensity = 2;

/// A white floor y = 0 seen straight down from `height` with a square image.
SceneMaker floorScene(double height, double fov) {
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, height, 0}, {0, 0, 0}, fov);
    camera.up = {0, 0, 1}; // image x runs along world +x
    m.desc = blankScene(kSize, kSize, camera);
    ShadingMaterial white;
    white.color = scene::Color{1, 1, 1, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(white)));
    return m;
}

scene::LightDesc cylinderLight(DVec3 from, DVec3 to) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Cylinder;
    l.from = from;
    l.to = to;
    l.color = scene::Color{kIntensity, kIntensity, kIntensity, 1};
    return l;
}

/// ∫ h / sqrt((s - x)² + a²) ds for s from s0 to s1: the cosine term of a segment along x at
/// height h, seen from floor point (x, 0, z), a² = h² + z².
double cosineIntegral(double x, double z, double h, double s0, double s1) {
    double a = std::sqrt(h * h + z * z);
    return h * (std::asinh((s1 - x) / a) - std::asinh((s0 - x) / a));
}

/// The floor point a pixel sees.
DVec3 floorPoint(const scene::SceneDesc& desc, int x, int y) {
    TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
    auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
    REQUIRE(t);
    return ray.at(*t);
}

} // namespace

TEST_CASE("a cylinder light lights a floor with the exact integral along its length",
          "[render][analytic][cylinder]") {
    const double h = 1.5, half = 2;
    SceneMaker m = floorScene(6, 60);
    m.desc.settings.shadowSamples = 256;
    m.desc.lights.push_back(cylinderLight({-half, h, 0}, {half, h, 0}));
    PixelBuffer image = renderOk(m.desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            DVec3 p = floorPoint(m.desc, x, y);
            double want = kIntensity / (2 * half) * cosineIntegral(p.x, p.z, h, -half, half);
            INFO("pixel " << x << "," << y << " at " << p.x << "," << p.z);
            CHECK(pixelAt(image, x, y).x == Approx(want).epsilon(1e-3)); // 256 jittered strata
        }
}

TEST_CASE("with inverse-square attenuation the cylinder light is I / (h sqrt(L²/4 + h²)) below "
          "its centre",
          "[render][analytic][cylinder]") {
    // (I/L)·∫ h / d³ ds from -L/2 to L/2 = I / (h·sqrt(L²/4 + h²)).
    for (double h : {0.5, 1.0, 3.0}) {
        const double length = 2;
        SceneMaker m = floorScene(6, 30);
        m.desc.settings.shadowSamples = 256;
        scene::LightDesc light = cylinderLight({-length / 2, h, 0}, {length / 2, h, 0});
        light.attenuation = {0, 0, 1};
        m.desc.lights.push_back(light);
        PixelBuffer image = renderOk(m.desc);
        double want = kIntensity / (h * std::sqrt(length * length / 4 + h * h));
        INFO("height " << h);
        CHECK(pixelAt(image, kSize / 2, kSize / 2).x == Approx(want).epsilon(1e-4));
    }
}

TEST_CASE("far away a cylinder light is a point light of the same colour at its centre",
          "[render][analytic][cylinder]") {
    const DVec3 centre{0.5, 100, -0.25};
    SceneMaker m = floorScene(10, 60);
    m.desc.lights.push_back(
        cylinderLight(centre - DVec3(0.5, 0, 0.2), centre + DVec3(0.5, 0, 0.2)));
    PixelBuffer tube = renderOk(m.desc);
    scene::LightDesc point;
    point.origin = centre;
    point.color = m.desc.lights[0].color;
    m.desc.lights[0] = point;
    PixelBuffer reference = renderOk(m.desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            INFO("pixel " << x << "," << y);
            CHECK(pixelAt(tube, x, y).x == Approx(pixelAt(reference, x, y).x).epsilon(1e-4));
        }
}

TEST_CASE("a cylinder light casts a soft shadow: umbra, a monotone penumbra, full light",
          "[render][analytic][cylinder]") {
    // The tube runs along x from -2 to 2 at height 4; an opaque sheet at height 1 covers x < 0.
    // The floor point (x, 0, z) sees the tube where the line to it passes y = 1 at x >= 0, that
    // is where s >= -3x: all of it for x >= 2/3, none for x <= -2/3.
    const double h = 4, half = 2;
    SceneMaker m = floorScene(0.5, 120); // below the sheet, seeing x in about (-0.87, 0.87)
    m.desc.settings.shadowSamples = 256;
    m.desc.lights.push_back(cylinderLight({-half, h, 0}, {half, h, 0}));
    m.draw(m.entity(scene::QuadShape{{-100, 1, -100}, {100, 0, 0}, {0, 0, 200}}, -1, false));
    PixelBuffer image = renderOk(m.desc);

    int umbra = 0, penumbra = 0, lit = 0;
    for (int y = 0; y < kSize; ++y) {
        double previous = -1;
        for (int x = 0; x < kSize; ++x) {
            DVec3 p = floorPoint(m.desc, x, y);
            double full = kIntensity / (2 * half) * cosineIntegral(p.x, p.z, h, -half, half);
            double s0 = std::clamp(-3 * p.x, -half, half);
            double want = kIntensity / (2 * half) * cosineIntegral(p.x, p.z, h, s0, half);
            double got = pixelAt(image, x, y).x;
            INFO("pixel " << x << "," << y << " at x = " << p.x);
            // One stratum in 256 may straddle the shadow's edge.
            CHECK(std::abs(got - want) <= full / 256 + 1e-6 * full);
            if (y == kSize / 2) {
                // The part of the tube seen grows towards the open side (up to one stratum).
                double seen = got / full;
                CHECK(seen >= previous - 1.0 / 256);
                CHECK(seen <= 1 + 1e-3); // the strata estimate the integral closely
                previous = seen;
            }
            if (want == 0)
                ++umbra;
            else if (want == full)
                ++lit;
            else
                ++penumbra;
        }
    }
    CHECK(umbra > 50);
    CHECK(lit > 50);
    CHECK(penumbra > 200);
}

TEST_CASE("a cylinder light's samples are deterministic for any thread count",
          "[render][cylinder]") {
    SceneMaker m = floorScene(0.5, 120);
    m.desc.settings.shadowSamples = 5;
    m.desc.lights.push_back(cylinderLight({-2, 4, 0}, {2, 4, 0}));
    m.draw(m.entity(scene::QuadShape{{-100, 1, -100}, {100, 0, 0}, {0, 0, 200}}, -1, false));
    PixelBuffer one = renderOk(m.desc, 1);
    CHECK(renderOk(m.desc, 3).pixels == one.pixels);
    CHECK(renderOk(m.desc, 2).pixels == one.pixels);
}
