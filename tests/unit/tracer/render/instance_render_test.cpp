// An entity drawn many times (a group, a CSG solid) is built once and instanced: the picture
// is the one its copies make, each drawing with its own transform and material, shadows and
// reflections between the drawings included; picking names what copies would name.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "tracer/pick.hpp"
#include "tracer/render_scene.hpp"

#include <set>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kWidth = 96, kHeight = 64;

/// A little tree: a trunk (a cylinder minus a sphere), a crown of 13 spheres and a mirror
/// ball: 16 primitives. Every coordinate is a multiple of 1/16, so moving it
/// by whole units is exact.
int32_t tree(SceneMaker& m, int32_t mirror) {
    std::vector<int32_t> parts;
    const int32_t trunk = m.entity(scene::CylinderShape{{0, 0, 0}, {0, 0.5, 0}, 0.0625, false});
    parts.push_back(m.csg(scene::CsgOp::Difference, trunk, m.sphere({0.0625, 0.25, 0}, 0.0625)));
    for (int k = 0; k < 13; ++k) {
        const double x = (k % 3 - 1) * 0.125, z = (k / 3 % 2) * 0.125 - 0.0625, y = 0.5 + (k / 6) * 0.125;
        parts.push_back(m.sphere({x, y, z}, 0.125));
    }
    parts.push_back(m.sphere({0, 0.875, 0}, 0.0625, mirror));
    return m.entity(scene::GroupNode{parts});
}

/// 4 × 4 trees, each with its own colour (given to the parts that have none), on a floor.
/// Shared: one tree entity drawn 16 times; copied: 16 tree entities.
scene::SceneDesc forest(bool shared) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, lookAt({1.5, 2.5, -2}, {1.5, 0.25, 1.5}, 60));
    m.desc.settings.ambient = scene::Color{0.1, 0.1, 0.1, 1};
    m.desc.lights.push_back(parallelLight({-2, 3, -1}));
    ShadingMaterial chrome;
    chrome.color = scene::Color{0.9, 0.9, 0.9, 1};
    chrome.reflectivity = 0.8;
    const int32_t mirror = m.material(chrome);
    const int32_t one = tree(m, mirror);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const int32_t drawn = shared ? one : tree(m, mirror);
            m.draw(m.transformed(drawn, {translate({i, 0, j})}, m.colored(0.2 + 0.2 * i, 0.8 - 0.2 * j, 0.3)));
        }
    }
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.colored(0.7, 0.7, 0.7)));
    return m.desc;
}

} // namespace

TEST_CASE("An entity drawn many times is built once and renders as its copies do", "[render][instance]") {
    const scene::SceneDesc shared = forest(true), copied = forest(false);
    std::string error;
    const auto sharedScene = buildRenderScene(shared, error);
    const auto copiedScene = buildRenderScene(copied, error);
    REQUIRE(sharedScene);
    REQUIRE(copiedScene);
    CHECK(sharedScene->prototypes.size() == 1);
    CHECK(sharedScene->instances.size() == 16);
    CHECK(copiedScene->instances.empty());
    // A tree's 16 primitives stored once, 16 drawings and the floor; or 16 trees and the floor.
    CHECK(sharedScene->storedPrimitives() == 16 + 16 + 1);
    CHECK(copiedScene->storedPrimitives() == 16 * 16 + 1);

    const PixelBuffer a = renderOk(shared), b = renderOk(copied);
    int differing = 0, lit = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            differing += maxDifference(pixelAt(a, x, y), pixelAt(b, x, y)) > 1e-6;
            lit += maxDifference(pixelAt(a, x, y), DVec3(0.0)) > 0.05;
        }
    }
    CHECK(differing == 0);
    CHECK(lit > kWidth * kHeight / 2);
}

TEST_CASE("A ray leaving an instance's face skips that face only", "[render][instance]") {
    const scene::SceneDesc shared = forest(true);
    std::string error;
    const auto scene = buildRenderScene(shared, error);
    REQUIRE(scene);
    QueryScratch scratch;
    RayStats stats;
    int instanceHits = 0;
    for (int k = 0; k < 1600; ++k) {
        const Ray camera{{1.5, 2.5, -2}, glm::normalize(Vec3(0.0625 * (k % 40) - 1.25, -1.5, 3.5 + 0.05 * (k / 40)))};
        Hit hit;
        if (!scene->intersect(camera, kInfinity, hit, scratch, stats) || hit.instance < 0) continue;
        ++instanceHits;
        const SurfaceInteraction si = scene->interaction(camera, hit);
        const Vec3 out = si.normal;
        const Departure departed = scene->departedPrimitive(hit, si, out);
        if (departed.primitive < 0) continue; // a cut face of the trunk
        CHECK(departed.instance == hit.instance);
        CHECK(departed.primitive == hit.primitive);
        // The departed face is never met again; the same primitive in another drawing is.
        scene->forEachCrossing(Ray{si.point + 1e-9 * out, out}, kInfinity, departed, scratch, stats,
                               [&](const Hit& h) {
                                   CHECK_FALSE((h.instance == hit.instance && h.primitive == hit.primitive));
                                   return true;
                               });
    }
    CHECK(instanceHits > 200);
}

TEST_CASE("Picking a drawing of a shared entity names its part and the drawing's material", "[render][instance]") {
    const scene::SceneDesc shared = forest(true), copied = forest(false);
    // The shared tree is the description's only group; its parts come before it.
    int32_t sharedTree = -1;
    for (size_t e = 0; e < shared.entities.size() && sharedTree < 0; ++e)
        if (std::holds_alternative<scene::GroupNode>(shared.entities[e].shape)) sharedTree = static_cast<int32_t>(e);
    REQUIRE(sharedTree > 0);
    std::string error;
    int treeParts = 0;
    std::set<int32_t> materials;
    for (int y = 2; y < kHeight; y += 4) {
        for (int x = 2; x < kWidth; x += 4) {
            const auto a = pick(shared, x, y, error), b = pick(copied, x, y, error);
            REQUIRE(a);
            REQUIRE(b);
            CHECK(a->hit == b->hit);
            CHECK(a->material == b->material);
            CHECK(a->distance == b->distance);
            const scene::EntityDesc& picked = shared.entities[static_cast<size_t>(a->entity)];
            if (a->hit && !std::holds_alternative<scene::PlaneShape>(picked.shape)) {
                CHECK(a->entity < sharedTree);
                ++treeParts;
                materials.insert(a->material);
            }
        }
    }
    CHECK(treeParts > 50);
    CHECK(materials.size() > 8); // the drawings' own colours, not one
}
