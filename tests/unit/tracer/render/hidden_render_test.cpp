// Entities hidden from some rays (`camera`, `shadow`, `reflected` set false): each kind of
// ray crosses what is hidden from it as if it were not there, and the others still meet it.
//
// A white floor lit by a parallel light from the side, a sphere above it: every floor pixel
// is the light's n·l, or 0 where the sphere shades it; both are computed here from the spec's
// camera ray, so each render is checked pixel by pixel against what it should show.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "tracer/pick.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 32;
const DVec3 kCenter{0, 1, 0};
constexpr double kRadius = 0.8;
const DVec3 kToLight = glm::normalize(DVec3(1, 1, 0.3));
const DVec3 kSphereColor{0.2, 0.4, 0.9};

scene::SceneDesc floorAndSphere(uint8_t hidden) {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 4, -4}, {0, 0.5, 0}, 60));
    ShadingMaterial white;
    white.color = scene::Color{1, 1, 1, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(white)));
    ShadingMaterial glow; // seen as its emission alone, whatever lights it
    glow.color = scene::Color{0, 0, 0, 1};
    glow.diffuse = 0;
    glow.emission = scene::Color{kSphereColor.x, kSphereColor.y, kSphereColor.z, 1};
    const int32_t sphere = m.sphere(kCenter, kRadius, m.material(glow));
    m.desc.entities[static_cast<size_t>(sphere)].hidden = hidden;
    m.draw(sphere);
    m.desc.lights.push_back(parallelLight(kToLight, DVec3(0.0)));
    return m.desc;
}

/// What pixel (x, y) shows: the sphere if the camera sees it, else the floor, lit unless the
/// sphere casts a shadow there.
DVec3 expected(const scene::SceneDesc& desc, int x, int y, bool seen, bool castsShadow) {
    const TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
    if (seen && hitSphere(ray, kCenter, kRadius)) return kSphereColor;
    const auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
    if (!t) return DVec3(0.0);
    const TestRay toLight{ray.at(*t), kToLight};
    if (castsShadow && hitSphere(toLight, kCenter, kRadius)) return DVec3(0.0);
    return DVec3(kToLight.y);
}

/// Renders and compares every pixel but those on the sphere's or its shadow's edges, where a
/// pixel-centre test and the renderer's rounding may disagree.
void checkImage(uint8_t hidden, bool seen, bool castsShadow) {
    const scene::SceneDesc desc = floorAndSphere(hidden);
    const PixelBuffer image = renderOk(desc);
    int sphere = 0, shadow = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
            if (hitSphere(ray, kCenter, kRadius) && !hitSphere(ray, kCenter, kRadius, 0.02)) continue;
            const auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0});
            if (t && hitSphere({ray.at(*t), kToLight}, kCenter, kRadius) &&
                !hitSphere({ray.at(*t), kToLight}, kCenter, kRadius, 0.02))
                continue;
            const DVec3 want = expected(desc, x, y, seen, castsShadow);
            sphere += want == kSphereColor;
            shadow += want == DVec3(0.0) && t;
            INFO("pixel " << x << "," << y);
            CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-6);
        }
    // The view holds what each case is about.
    CHECK((sphere > 20) == seen);
    CHECK((shadow > 10) == castsShadow);
}

} // namespace

TEST_CASE("an entity hidden from the camera is not seen but casts its shadow", "[render][hidden]") {
    checkImage(0, true, true);
    checkImage(scene::kHiddenFromCamera, false, true);
}

TEST_CASE("an entity hidden from shadows is seen and casts none", "[render][hidden]") {
    checkImage(scene::kHiddenFromShadows, true, false);
    checkImage(scene::kHiddenFromShadows | scene::kHiddenFromCamera, false, false);
}

TEST_CASE("an entity hidden from reflections is seen directly, not in a mirror", "[render][hidden]") {
    // Looking down at a mirror floor: the sphere is seen in it unless hidden from reflections;
    // hidden from the camera, it is seen in the mirror alone (also through where it stands).
    for (uint8_t hidden : {uint8_t{0}, uint8_t{scene::kHiddenFromReflections}, uint8_t{scene::kHiddenFromCamera}}) {
        INFO("hidden " << int(hidden));
        scene::SceneDesc desc = floorAndSphere(hidden);
        desc.lights.clear();
        ShadingMaterial mirror;
        mirror.color = scene::Color{0, 0, 0, 1};
        mirror.diffuse = 0;
        mirror.reflectivity = 1;
        desc.materials[0] = {mirror.color, desc.internFinish(mirror), {}};
        const PixelBuffer image = renderOk(desc);
        int direct = 0, reflected = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const TestRay ray = specCameraRay(desc.camera, kSize, kSize, x, y);
                DVec3 want(0.0);
                const bool seen = !(hidden & scene::kHiddenFromCamera);
                if (seen && hitSphere(ray, kCenter, kRadius, 0.02)) {
                    want = kSphereColor;
                    ++direct;
                } else if (hitSphere(ray, kCenter, kRadius) && !hitSphere(ray, kCenter, kRadius, 0.02)) {
                    continue;
                } else if (const auto t = hitPlane(ray, {0, 1, 0}, {0, 0, 0})) {
                    const TestRay bounced{ray.at(*t), DVec3(ray.dir.x, -ray.dir.y, ray.dir.z)};
                    if (hitSphere(bounced, kCenter, kRadius) && !hitSphere(bounced, kCenter, kRadius, 0.02)) continue;
                    if (hitSphere(bounced, kCenter, kRadius) && !(hidden & scene::kHiddenFromReflections)) {
                        want = kSphereColor;
                        ++reflected;
                    }
                }
                INFO("pixel " << x << "," << y);
                CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-6);
            }
        CHECK((direct > 20) == !(hidden & scene::kHiddenFromCamera));
        CHECK((reflected > 5) == !(hidden & scene::kHiddenFromReflections));
    }
}

TEST_CASE("a drawing of a shared entity hidden from the camera hides that drawing only", "[render][hidden]") {
    // A cluster of glowing spheres drawn twice (an instance of one prototype each time), the
    // second drawing hidden from the camera: the image is that of the first drawing alone.
    auto cluster = [](bool second, uint8_t hidden) {
        SceneMaker m;
        m.desc = blankScene(kSize, kSize, lookAt({0, 0, -10}, {0, 0, 0}, 60));
        ShadingMaterial glow;
        glow.color = scene::Color{0, 0, 0, 1};
        glow.diffuse = 0;
        glow.emission = scene::Color{1, 0.5, 0.25, 1};
        const int32_t material = m.material(glow);
        int32_t group = m.sphere({0, 0, 0}, 0.2, material);
        for (int i = 1; i < 20; ++i)
            group = m.csg(scene::CsgOp::Union, group, m.sphere({0.3 * (i % 5), 0.3 * (i / 5), 0}, 0.2, material));
        m.draw(m.transformed(group, {translate({-2, 0, 0})}));
        if (second) {
            const int32_t moved = m.transformed(group, {translate({1, 0, 0})});
            m.desc.entities[static_cast<size_t>(moved)].hidden = hidden;
            m.draw(moved);
        }
        return m.desc;
    };
    std::string error;
    const auto built = buildRenderScene(cluster(true, scene::kHiddenFromCamera), error, 1);
    REQUIRE(built);
    REQUIRE(built->instances.size() == 2);
    CHECK(built->hidesAnything());
    const PixelBuffer alone = renderOk(cluster(false, 0));
    const PixelBuffer hidden = renderOk(cluster(true, scene::kHiddenFromCamera));
    const PixelBuffer both = renderOk(cluster(true, 0));
    CHECK(hidden.pixels == alone.pixels);
    CHECK(both.pixels != alone.pixels);
}

TEST_CASE("the path integrator crosses what is hidden from its camera rays and shadow rays",
          "[render][hidden]") {
    // A glowing wall seen through where a black sphere hidden from the camera stands; then
    // a sphere hidden from shadows between the wall and a floor it lights.
    auto scene = [](bool sphere, uint8_t hidden) {
        SceneMaker m;
        m.desc = blankScene(kSize, kSize, lookAt({0, 1, -5}, {0, 1, 0}, 50));
        m.desc.settings.integrator = scene::Integrator::Path;
        m.desc.settings.samples = 8;
        ShadingMaterial glow;
        glow.color = scene::Color{0, 0, 0, 1};
        glow.diffuse = 0;
        glow.emission = scene::Color{0.8, 0.7, 0.6, 1};
        m.draw(m.plane({0, 0, -1}, {0, 0, 3}, m.material(glow)));
        m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.colored(0.5, 0.5, 0.5)));
        if (sphere) {
            const int32_t s = m.sphere({0, 1, 1}, 0.7, m.colored(0, 0, 0));
            m.desc.entities[static_cast<size_t>(s)].hidden = hidden;
            m.draw(s);
        }
        return m.desc;
    };
    const PixelBuffer alone = renderOk(scene(false, 0));
    CHECK(renderOk(scene(true, scene::kHiddenFromCamera | scene::kHiddenFromShadows |
                                   scene::kHiddenFromReflections)).pixels == alone.pixels);
    // Hidden from the camera only, it still darkens the floor below it.
    const PixelBuffer unseen = renderOk(scene(true, scene::kHiddenFromCamera));
    const PixelBuffer seen = renderOk(scene(true, 0));
    CHECK(unseen.pixels != alone.pixels);
    CHECK(pixelAt(unseen, kSize / 2, kSize / 2) == pixelAt(alone, kSize / 2, kSize / 2));
    CHECK(pixelAt(seen, kSize / 2, kSize / 2) != pixelAt(alone, kSize / 2, kSize / 2));
}

TEST_CASE("picking names what the camera sees, not what is hidden from it", "[render][hidden]") {
    // The image's centre looks at the sphere; hidden from the camera, at the floor behind it.
    const scene::SceneDesc seen = floorAndSphere(0), unseen = floorAndSphere(scene::kHiddenFromCamera);
    const TestRay ray = specCameraRay(seen.camera, kSize, kSize, kSize / 2, kSize / 2);
    REQUIRE(hitSphere(ray, kCenter, kRadius, 0.05));
    const double floorDistance = *hitPlane(ray, {0, 1, 0}, {0, 0, 0});
    std::string error;
    const auto onSphere = pick(seen, kSize / 2 + 0.5, kSize / 2 + 0.5, error);
    const auto onFloor = pick(unseen, kSize / 2 + 0.5, kSize / 2 + 0.5, error);
    REQUIRE(onSphere);
    REQUIRE(onFloor);
    CHECK(onSphere->entity == 1);
    CHECK(onFloor->entity == 0);
    CHECK(onFloor->distance == Approx(floorDistance));
    CHECK(onFloor->point.y == Approx(0).margin(1e-9));
}
