// Visible lights and the sphere light, rendered: a visible light is seen where its shape is,
// as its colour, by the camera and in a mirror; a sphere light lights as the circular,
// oriented area light its description says it is.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 40;
const DVec3 kLamp{0.6, 1.5, 0.5};
constexpr double kLampRadius = 0.4;
const DVec3 kLampColor{0.9, 0.8, 0.5};

scene::LightDesc sphereLight(bool visible) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Sphere;
    l.origin = kLamp;
    l.radius = kLampRadius;
    l.color = {kLampColor.x, kLampColor.y, kLampColor.z, 1};
    l.visible = visible;
    return l;
}

/// A grey floor and a ball under the lamp, seen from the front and above.
scene::SceneDesc litScene(const scene::LightDesc& light, bool mirrorFloor = false) {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 2.5, -4}, {0.3, 0.6, 0.5}, 55));
    m.desc.background.color = {0.1, 0.2, 0.3, 1};
    ShadingMaterial floor;
    floor.color = scene::Color{0.6, 0.6, 0.6, 1};
    if (mirrorFloor) {
        floor.color = scene::Color{0, 0, 0, 1};
        floor.diffuse = 0;
        floor.reflectivity = 1;
    }
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    m.draw(m.sphere({-0.3, 0.35, 0.2}, 0.35, m.colored(0.8, 0.3, 0.2)));
    m.desc.lights.push_back(light);
    m.desc.settings.shadowSamples = 16;
    return m.desc;
}

} // namespace

TEST_CASE("a sphere light lights as the circular area light facing each point", "[render][lights]") {
    scene::LightDesc disc = sphereLight(false);
    disc.kind = scene::LightKind::Area;
    disc.edgeA = {2 * kLampRadius, 0, 0};
    disc.edgeB = {0, 0, 2 * kLampRadius};
    disc.origin = kLamp - 0.5 * (disc.edgeA + disc.edgeB);
    disc.circular = disc.orient = true;
    const PixelBuffer sphere = renderOk(litScene(sphereLight(false)));
    CHECK(renderOk(litScene(disc)).pixels == sphere.pixels);
    // Not a point light: its shadow is soft.
    scene::LightDesc point = sphereLight(false);
    point.kind = scene::LightKind::Point;
    CHECK(renderOk(litScene(point)).pixels != sphere.pixels);
}

TEST_CASE("a visible light is seen as its colour where its shape is, directly and in a mirror",
          "[render][lights]") {
    for (bool mirror : {false, true}) {
        INFO((mirror ? "mirror floor" : "grey floor"));
        const scene::SceneDesc desc = litScene(sphereLight(true), mirror);
        const PixelBuffer seen = renderOk(desc);
        const PixelBuffer unseen = renderOk(litScene(sphereLight(false), mirror));
        int direct = 0, reflected = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
                INFO("pixel " << x << "," << y);
                if (hitSphere(ray, kLamp, kLampRadius, 0.02)) {
                    CHECK(maxDifference(pixelAt(seen, x, y), kLampColor) < 1e-6);
                    ++direct;
                } else if (hitSphere(ray, kLamp, kLampRadius)) {
                    continue; // its edge
                } else if (const auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0}); t && mirror) {
                    const TestRay bounced{ray.at(*t), DVec3(ray.dir.x, -ray.dir.y, ray.dir.z)};
                    if (hitSphere(bounced, kLamp, kLampRadius, 0.02) && !hitSphere(bounced, {-0.3, 0.35, 0.2}, 0.36)) {
                        CHECK(maxDifference(pixelAt(seen, x, y), kLampColor) < 1e-6);
                        ++reflected;
                    }
                }
            }
        CHECK(direct > 20);
        CHECK(reflected > (mirror ? 10 : -1));
        // Where it is not, the images agree: the visible light lights as the unseen one.
        int same = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) same += pixelAt(seen, x, y) == pixelAt(unseen, x, y);
        CHECK(same + direct + reflected >= kSize * kSize - 40);
    }
}

TEST_CASE("the path integrator's camera sees a visible light as its colour", "[render][lights]") {
    scene::SceneDesc desc = litScene(sphereLight(true));
    desc.settings.integrator = scene::Integrator::Path;
    desc.settings.samples = 4;
    const PixelBuffer image = renderOk(desc);
    int direct = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
            if (!hitSphere(ray, kLamp, kLampRadius, 0.05)) continue;
            INFO("pixel " << x << "," << y);
            CHECK(maxDifference(pixelAt(image, x, y), kLampColor) < 1e-6);
            ++direct;
        }
    CHECK(direct > 10);
}
