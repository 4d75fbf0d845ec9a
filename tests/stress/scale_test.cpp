// Numerical stability across scales: no shadow acne or self-reflection speckles at 1e-3 or 1e5.
//
// Spawned rays are offset by a bound on the hit point's error, not a fixed epsilon (spec §6,
// "Robustness"), so a scene scaled uniformly must look the same at every scale: the 8-bit images
// may differ by at most 1/255 per channel on 99.9% of pixels (rounding of the scaled coordinates
// can flip a pixel at an edge, nothing more).
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kWidth = 160, kHeight = 120;

/// A sphere resting on a slightly reflective floor, a mirror sphere and a mirror wall, lit by a
/// point light (no falloff, so the lighting is scale-free) and a parallel light; all lengths × s.
scene::SceneDesc scaledScene(double s) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, lookAt(DVec3(0.5, 2.2, -5) * s, DVec3(0.3, 0.8, 0) * s, 50));
    m.desc.settings.recursionDepth = 5;
    m.desc.background.kind = scene::BackgroundKind::Gradient;
    m.desc.background.horizon = scene::Color{0.8, 0.85, 0.9, 1};
    m.desc.background.sky = scene::Color{0.3, 0.5, 0.9, 1};

    ShadingMaterial floor;
    floor.color = scene::Color{0.6, 0.6, 0.55, 1};
    floor.reflectivity = 0.2;
    floor.diffuse = 0.8;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    ShadingMaterial red;
    red.color = scene::Color{0.8, 0.3, 0.2, 1};
    red.specular = 0.4;
    red.shininess = 20;
    m.draw(m.sphere(DVec3(0, 1, 0) * s, 1 * s, m.material(red))); // touches the floor
    ShadingMaterial mirror;
    mirror.color = scene::Color{0.9, 0.9, 0.9, 1};
    mirror.reflectivity = 0.9;
    mirror.diffuse = 0.1;
    m.draw(m.sphere(DVec3(1.9, 0.8, 0.6) * s, 0.8 * s, m.material(mirror)));
    ShadingMaterial wall = mirror;
    wall.reflectivity = 0.7;
    wall.diffuse = 0.3;
    m.draw(m.plane({0, 0, -1}, DVec3(0, 0, 4) * s, m.material(wall)));

    scene::LightDesc point;
    point.kind = scene::LightKind::Point;
    point.origin = DVec3(-3, 5, -3) * s;
    point.color = scene::Color{0.8, 0.8, 0.8, 1};
    m.desc.lights.push_back(point);
    scene::LightDesc sun;
    sun.kind = scene::LightKind::Parallel;
    sun.from = DVec3(1, 3, -2);
    sun.pointing = DVec3(0, 0, 0);
    sun.color = scene::Color{0.3, 0.3, 0.3, 1};
    m.desc.lights.push_back(sun);
    return m.desc;
}

/// The 8-bit codes an output file would hold (gamma 1).
std::vector<int> quantised(const PixelBuffer& image) {
    std::vector<int> codes(image.rgb.size());
    for (size_t i = 0; i < codes.size(); ++i)
        codes[i] = static_cast<int>(std::floor(255 * std::clamp(static_cast<double>(image.rgb[i]), 0.0, 1.0) + 0.5));
    return codes;
}

} // namespace

TEST_CASE("A scene scaled by 1e-3 and 1e5 renders like the unit scene", "[stress][scale]") {
    std::vector<int> unit = quantised(renderOk(scaledScene(1)));
    for (double s : {1e-3, 1e5}) {
        std::vector<int> scaled = quantised(renderOk(scaledScene(s)));
        REQUIRE(scaled.size() == unit.size());
        int worst = 0, badPixels = 0;
        for (size_t p = 0; p < unit.size(); p += 3) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(scaled[p + c] - unit[p + c]));
            worst = std::max(worst, d);
            badPixels += d > 1;
        }
        double allowed = 0.001 * kWidth * kHeight;
        INFO("scale " << s << ": " << badPixels << " pixels differ by more than 1/255 (allowed " << allowed
                      << "), largest difference " << worst << "/255");
        CHECK(badPixels <= allowed);
        WARN("scale " << s << ": largest difference " << worst << "/255, " << badPixels << " pixels over 1/255");
    }
}

TEST_CASE("A lit floor and sphere have no shadow acne at scales 1e-3, 1 and 1e5", "[stress][scale]") {
    // Exact Lambert values wherever a point sees the light, so a single self-shadowed (acne)
    // pixel fails, at every scale; the relative tolerance absorbs float storage only.
    for (double s : {1e-3, 1.0, 1e5}) {
        SceneMaker m;
        m.desc = blankScene(96, 72, lookAt(DVec3(0.5, 2.2, -5) * s, DVec3(0.3, 0.8, 0) * s, 50));
        const scene::Color C{0.7, 0.6, 0.5, 1};
        ShadingMaterial mat;
        mat.color = C;
        int32_t id = m.material(mat);
        const DVec3 center = DVec3(0, 1, 0) * s;
        const double radius = s;
        m.draw(m.plane({0, 1, 0}, {0, 0, 0}, id));
        m.draw(m.sphere(center, radius, id));
        scene::LightDesc sun;
        sun.kind = scene::LightKind::Parallel;
        sun.from = {-1, 4, -2};
        sun.pointing = {0, 0, 0};
        m.desc.lights.push_back(sun);
        const DVec3 l = glm::normalize(sun.from - sun.pointing);
        PixelBuffer image = renderOk(m.desc);
        int checked = 0;
        for (int y = 0; y < m.desc.settings.height; ++y) {
            for (int x = 0; x < m.desc.settings.width; ++x) {
                TestRay ray = specCameraRay(m.desc.camera, m.desc.settings.width, m.desc.settings.height, x, y);
                DVec3 n, p;
                if (auto t = hitSphere(ray, center, radius, 1e-3 * s)) {
                    p = ray.at(*t);
                    n = (p - center) / radius;
                } else if (hitSphere(ray, center, radius + 1e-3 * s)) {
                    continue;
                } else if (auto tp = hitPlane(ray, {0, 1, 0}, {0, 0, 0})) {
                    p = ray.at(*tp);
                    n = {0, 1, 0};
                    // In or near the sphere's shadow: not a pixel for this check.
                    DVec3 toCenter = center - p;
                    double along = glm::dot(toCenter, l);
                    if (along > 0 && glm::length(toCenter - along * l) < radius * 1.01) continue;
                } else {
                    continue;
                }
                double cosTheta = glm::dot(n, l);
                if (cosTheta < 0.05) continue; // the terminator: shadowed or nearly so
                DVec3 want = rgbOf(C) * cosTheta;
                DVec3 got = pixelAt(image, x, y);
                INFO("scale " << s << " pixel " << x << "," << y << " want " << want.x << " got " << got.x);
                CHECK(maxDifference(got, want) < 1e-4);
                ++checked;
            }
        }
        CHECK(checked > 2500);
    }
}
