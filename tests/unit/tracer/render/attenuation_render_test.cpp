// Analytic render tests of light attenuation (CS 488's 1 / (c0 + c1·d + c2·d²), d the distance
// from the lit point to the light), alone and together with the path-length falloff.
//
// A white diffuse floor seen from straight above, lit from above: every pixel is the spec's
// C·kd·L·(n·l)·F with F computed here from the light's distance at the pixel's hit point.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 15;
const DVec3 kCamera{0, 10, 0};
constexpr double kLightIntensity = 4;

scene::SceneDesc litFloor(const scene::LightDesc& light) {
    SceneMaker m;
    scene::CameraDesc camera = lookAt(kCamera, {0, 0, 0}, 60);
    camera.up = {0, 0, 1}; // the view is straight down
    m.desc = blankScene(kSize, kSize, camera);
    ShadingMaterial white;
    white.color = scene::Color{1, 1, 1, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(white)));
    m.desc.lights.push_back(light);
    return m.desc;
}

scene::LightDesc pointLight(DVec3 origin, DVec3 attenuation, double falloff = 0) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Point;
    l.origin = origin;
    l.color = scene::Color{kLightIntensity, kLightIntensity, kLightIntensity, 1};
    l.attenuation = attenuation;
    l.falloff = falloff;
    return l;
}

/// Checks every pixel against C·kd·L·(n·l)·falloff·attenuation for a light at `origin`.
void checkFloor(const scene::SceneDesc& desc, DVec3 origin, double tolerance) {
    const scene::LightDesc& light = desc.lights[0];
    PixelBuffer image = renderOk(desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
            auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            REQUIRE(t);
            DVec3 p = ray.at(*t);
            double d = glm::length(origin - p);
            double nDotL = (origin.y - p.y) / d;
            double f = 1;
            if (light.falloff > 0) f = light.falloff / ((d + *t) * (d + *t));
            DVec3 c = light.attenuation;
            double want = kLightIntensity * nDotL * f / (c.x + c.y * d + c.z * d * d);
            INFO("pixel " << x << "," << y << " distance " << d << " want " << want);
            CHECK(std::abs(pixelAt(image, x, y).x - want) <= tolerance * want);
        }
}

} // namespace

TEST_CASE("attenuation divides a point light by c0 + c1 d + c2 d^2", "[render][analytic]") {
    const DVec3 origin{0.5, 2, -0.25};
    for (DVec3 terms : {DVec3(1, 0, 0), DVec3(0, 0, 1), DVec3(0, 1, 0), DVec3(0.5, 0.25, 0.125),
                        DVec3(2, 0, 0)}) {
        INFO("attenuation " << terms.x << " " << terms.y << " " << terms.z);
        checkFloor(litFloor(pointLight(origin, terms)), origin, 1e-6);
    }
}

TEST_CASE("at known distances an attenuated point light is 1 / (c0 + c1 d + c2 d^2) of itself",
          "[render][analytic]") {
    // The centre pixel looks straight down at the origin: n·l = 1 and d is the light's height.
    for (double h : {0.5, 1.0, 2.0, 4.0, 8.0}) {
        const DVec3 terms(0.5, 0.25, 0.125);
        PixelBuffer image = renderOk(litFloor(pointLight({0, h, 0}, terms)));
        double want = kLightIntensity / (0.5 + 0.25 * h + 0.125 * h * h);
        INFO("height " << h);
        CHECK(pixelAt(image, kSize / 2, kSize / 2).x == Approx(want).epsilon(1e-6));
    }
}

TEST_CASE("attenuation multiplies the path-length falloff", "[render][analytic]") {
    const DVec3 origin{-0.5, 3, 0.5};
    checkFloor(litFloor(pointLight(origin, {1, 0.5, 0}, 40)), origin, 1e-6);
    checkFloor(litFloor(pointLight(origin, {0, 0, 2}, 40)), origin, 1e-6);
}

TEST_CASE("attenuation applies to spot and area lights", "[render][analytic]") {
    const DVec3 origin{0.25, 2, 0};
    SECTION("a spot light, everything inside its full-intensity cone") {
        scene::LightDesc spot = pointLight(origin, {0.25, 0.5, 0.25});
        spot.kind = scene::LightKind::Spot;
        spot.pointing = origin - DVec3(0, 1, 0);
        spot.angle = 170;
        spot.softness = 0;
        checkFloor(litFloor(spot), origin, 1e-6);
    }
    SECTION("a tiny area light is a point light with the same attenuation") {
        const double side = 1e-4;
        scene::LightDesc area = pointLight(origin - DVec3(side / 2, 0, side / 2), {0, 0.5, 1});
        area.kind = scene::LightKind::Area;
        area.edgeA = {side, 0, 0};
        area.edgeB = {0, 0, side};
        checkFloor(litFloor(area), origin, 1e-3);
    }
}
