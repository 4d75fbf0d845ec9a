// Analytic render tests of direct lighting (spec §6): Lambert, falloff, spot cones, shadows.
//
// Each test renders a small image with render() and recomputes every checked pixel from the
// spec's formulas. Tolerance 1e-4 per channel: the renderer works in doubles and stores floats,
// so honest differences are ~1e-7, while any formula error is orders of magnitude larger (and
// 1e-4 is still 40 times finer than one 8-bit output step).
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr double kTolerance = 1e-4;

scene::LightDesc pointLight(DVec3 origin, scene::Color color, double falloff = 0) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Point;
    l.origin = origin;
    l.color = color;
    l.falloff = falloff;
    return l;
}

/// Distance from `c` to the segment a–b.
double segmentDistance(DVec3 a, DVec3 b, DVec3 c) {
    DVec3 ab = b - a;
    double s = std::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(a + s * ab - c);
}

} // namespace

TEST_CASE("A Lambert sphere under a parallel light is color x light x cos(theta) per pixel", "[render][analytic]") {
    const int W = 64, H = 48;
    SceneMaker m;
    // An off-axis camera, so the test exercises the general right/up basis of the spec's formula.
    m.desc = blankScene(W, H, lookAt({0.7, 0.4, -5}, {0.1, -0.1, 0}, 40));
    const DVec3 center(0.1, -0.2, 0.3);
    const double radius = 1;
    const scene::Color C{0.8, 0.6, 0.4, 1};
    const scene::Color L{0.9, 0.7, 1.0, 1};
    ShadingMaterial mat;
    mat.color = C; // diffuse 1, specular 0, no ambient anywhere
    m.draw(m.sphere(center, radius, m.material(mat)));
    const DVec3 from(-3, 2, -1), pointing(0, 0, 0);
    m.desc.lights.push_back(parallelLight(from, pointing, L));
    PixelBuffer image = renderOk(m.desc);

    const DVec3 l = glm::normalize(from - pointing); // unit direction to the light
    int lit = 0, unlit = 0, background = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " got " << got.x << " " << got.y << " " << got.z);
            if (auto t = hitSphere(ray, center, radius, 1e-3)) {
                DVec3 n = (ray.at(*t) - center) / radius;
                double cosTheta = std::max(0.0, glm::dot(n, l));
                DVec3 want = rgbOf(C) * rgbOf(L) * cosTheta;
                CHECK(maxDifference(got, want) < kTolerance);
                (cosTheta > 0 ? lit : unlit)++;
            } else if (!hitSphere(ray, center, radius + 1e-3)) {
                CHECK(got == DVec3(0.0));
                ++background;
            }
        }
    }
    // The view shows a good share of each case, so the checks above are not vacuous.
    CHECK(lit > 200);
    CHECK(unlit > 30);
    CHECK(background > 500);
}

TEST_CASE("A point light's falloff is falloff / (d + path)^2 on a plane, ambient terms unattenuated",
          "[render][analytic]") {
    const int W = 64, H = 48;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0, 2, -3}, {0, 0, 1}, 50));
    const scene::Color C{0.7, 0.5, 0.3, 1};
    const scene::Color L{1.0, 0.9, 0.8, 1};
    const DVec3 lightPos(0.5, 1.5, 1);
    const double falloff = 10, lightAmbient = 0.1;
    const DVec3 A(0.05, 0.04, 0.03);
    m.desc.settings.ambient = scene::Color{A.x, A.y, A.z, 1};
    ShadingMaterial mat;
    mat.color = C;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(mat)));
    scene::LightDesc light = pointLight(lightPos, L, falloff);
    light.ambient = lightAmbient;
    m.desc.lights.push_back(light);

    PixelBuffer image = renderOk(m.desc);
    int checked = 0;
    double strongest = 0, weakest = 1e9;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " got " << got.x << " " << got.y << " " << got.z);
            auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            if (!t) {
                CHECK(got == DVec3(0.0));
                continue;
            }
            DVec3 p = ray.at(*t);
            double d = glm::length(lightPos - p);
            double nDotL = (lightPos - p).y / d;
            double F = falloff / ((d + *t) * (d + *t)); // spec §6: d plus the camera-to-hit path
            DVec3 want = A * rgbOf(C) + lightAmbient * rgbOf(L) * rgbOf(C) + rgbOf(C) * rgbOf(L) * nDotL * F;
            CHECK(maxDifference(got, want) < kTolerance);
            strongest = std::max(strongest, F);
            weakest = std::min(weakest, F);
            ++checked;
        }
    }
    CHECK(checked > W * H / 2);
    CHECK(strongest > 2 * weakest); // the falloff really varies over the view
}

TEST_CASE("A spot light is full inside its cone, zero outside and smooth in between", "[render][analytic]") {
    const int W = 80, H = 60;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0, 5, -4}, {0, 0, 0.5}, 40));
    const scene::Color C{0.8, 0.8, 0.8, 1};
    ShadingMaterial mat;
    mat.color = C;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(mat)));
    const DVec3 lightPos(0, 3, 0), axis(0, -1, 0);
    const double fullAngle = 60, softness = 0.5;
    scene::LightDesc spot = pointLight(lightPos, scene::Color{1, 1, 1, 1});
    spot.kind = scene::LightKind::Spot;
    spot.pointing = lightPos + axis;
    spot.angle = fullAngle;
    spot.softness = softness;
    m.desc.lights.push_back(spot);
    PixelBuffer image = renderOk(m.desc);

    const double outer = fullAngle / 2, inner = outer * (1 - softness); // degrees from the axis
    struct Soft { double angle, factor; };
    std::vector<Soft> band;
    int inside = 0, outside = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            if (!t) continue;
            DVec3 p = ray.at(*t);
            DVec3 toPoint = glm::normalize(p - lightPos);
            double angle = std::acos(std::clamp(glm::dot(toPoint, axis), -1.0, 1.0)) * 180 / kTestPi;
            DVec3 full = rgbOf(C) * -toPoint.y; // Lambert with n = +y, no falloff
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " angle " << angle << " got " << got.x);
            if (angle < inner - 0.25) {
                CHECK(maxDifference(got, full) < kTolerance);
                ++inside;
            } else if (angle > outer + 0.25) {
                CHECK(got == DVec3(0.0));
                ++outside;
            } else if (angle > inner + 0.25 && angle < outer - 0.25) {
                double factor = got.x / full.x;
                CHECK(factor > 0);
                CHECK(factor < 1);
                CHECK(maxDifference(got, full * factor) < kTolerance); // a scalar factor: colour kept
                band.push_back({angle, factor});
            }
        }
    }
    CHECK(inside > 100);
    CHECK(outside > 100);
    REQUIRE(band.size() > 50);
    // Smooth: the factor falls monotonically with the angle and passes near one half mid-band.
    std::sort(band.begin(), band.end(), [](const Soft& a, const Soft& b) { return a.angle < b.angle; });
    for (size_t i = 1; i < band.size(); ++i) CHECK(band[i].factor <= band[i - 1].factor + 1e-6);
    double middle = (inner + outer) / 2;
    for (const Soft& s : band)
        if (std::abs(s.angle - middle) < 0.5) CHECK((s.factor > 0.3 && s.factor < 0.75));
}

namespace {

/// Plane y = 0 under a sphere and a point light; the sphere's material decides the shadow.
struct ShadowScene {
    static constexpr int W = 80, H = 60;
    SceneMaker m;
    DVec3 center{0, 1, 0};
    double radius = 0.5;
    DVec3 lightPos{0.3, 3, 0.2};
    scene::Color planeColor{0.6, 0.6, 0.6, 1};

    explicit ShadowScene(const ShadingMaterial& occluder) {
        m.desc = blankScene(W, H, lookAt({0, 4, -4}, {0, 0, 0.3}, 50));
        ShadingMaterial ground;
        ground.color = planeColor;
        m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(ground)));
        m.draw(m.sphere(center, radius, m.material(occluder)));
        m.desc.lights.push_back(pointLight(lightPos, scene::Color{1, 1, 1, 1}));
    }

    /// Calls visit(x, y, unshadowedColour, shadowed) for every plane pixel not seen through
    /// the sphere and not within a margin of the shadow's edge.
    template <typename Visit>
    void forPlanePixels(Visit visit) const {
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
                if (hitSphere(ray, center, radius + 1e-3)) continue;
                auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
                if (!t) continue;
                DVec3 p = ray.at(*t);
                double miss = segmentDistance(p, lightPos, center);
                if (std::abs(miss - radius) < 2e-3) continue;
                double nDotL = glm::normalize(lightPos - p).y;
                visit(x, y, rgbOf(planeColor) * nDotL, miss < radius);
            }
        }
    }
};

} // namespace

TEST_CASE("An opaque sphere casts a black shadow and leaves lit points untouched", "[render][analytic]") {
    ShadingMaterial opaque;
    opaque.color = scene::Color{0.9, 0.2, 0.2, 1};
    ShadowScene scene(opaque);
    PixelBuffer image = renderOk(scene.m.desc);
    int dark = 0, lit = 0;
    scene.forPlanePixels([&](int x, int y, DVec3 unshadowed, bool shadowed) {
        DVec3 got = pixelAt(image, x, y);
        INFO("pixel " << x << "," << y << " shadowed " << shadowed << " got " << got.x);
        if (shadowed) {
            CHECK(got == DVec3(0.0));
            ++dark;
        } else {
            CHECK(maxDifference(got, unshadowed) < kTolerance);
            ++lit;
        }
    });
    CHECK(dark > 30);
    CHECK(lit > 1000);
}

TEST_CASE("A transparent occluder attenuates by transparency x colour per surface crossing", "[render][analytic]") {
    ShadingMaterial glass;
    glass.color = scene::Color{1.0, 0.5, 0.25, 1};
    glass.transparency = 0.5;
    glass.diffuse = 0.5;
    glass.ior = 1; // only the shadow matters here
    ShadowScene scene(glass);
    PixelBuffer image = renderOk(scene.m.desc);
    // The shadow ray enters and leaves the sphere: two crossings.
    DVec3 perCrossing = 0.5 * rgbOf(glass.color);
    DVec3 through = perCrossing * perCrossing;
    int dim = 0;
    scene.forPlanePixels([&](int x, int y, DVec3 unshadowed, bool shadowed) {
        DVec3 got = pixelAt(image, x, y);
        INFO("pixel " << x << "," << y << " shadowed " << shadowed << " got " << got.x << " " << got.y << " "
                      << got.z);
        CHECK(maxDifference(got, shadowed ? unshadowed * through : unshadowed) < kTolerance);
        dim += shadowed;
    });
    CHECK(dim > 30);
}
