// CSG of convex solids (csg_convex.cpp) gives exactly the general merge's results.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <tuple>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// Lenses, carved blocks, a capped cylinder cut by a box, nested and transformed, plus
/// shapes whose faces coincide (which the convex path hands to the general merge).
scene::SceneDesc convexCsgScene() {
    SceneMaker m;
    int32_t lens = m.csg(scene::CsgOp::Intersection, m.sphere(Vec3(-0.6, 0, 0), 1), m.sphere(Vec3(0.6, 0, 0), 1));
    lens = m.csg(scene::CsgOp::Intersection, lens, m.sphere(Vec3(0, 0.7, 0), 1.1));
    lens = m.csg(scene::CsgOp::Intersection, lens, m.transformed(m.sphere(Vec3(0, 0, 0.4), 1), {scale(Vec3(1.2, 0.8, 1))}));
    m.draw(m.transformed(lens, {translate(Vec3(-3, 0, 0))}));

    int32_t carved = m.csg(scene::CsgOp::Difference, m.box(Vec3(-1), Vec3(1)), m.sphere(Vec3(0.7, 0.7, -0.5), 0.9));
    m.draw(m.transformed(carved, {rotate(Vec3(20, 35, 0)), translate(Vec3(0, 0, 0))}));

    scene::CylinderShape rod{Vec3(0, -1.5, 0), Vec3(0, 1.5, 0), 0.6, false};
    int32_t cutRod = m.csg(scene::CsgOp::Intersection, m.entity(rod), m.box(Vec3(-1, -1, -1), Vec3(1, 0.8, 0.3)));
    int32_t drilled = m.csg(scene::CsgOp::Difference, m.csg(scene::CsgOp::Intersection, m.box(Vec3(-1), Vec3(1)), m.sphere(Vec3(0), 1.3)),
                            m.transformed(m.entity(rod), {rotate(Vec3(90, 0, 0))}));
    m.draw(m.transformed(cutRod, {translate(Vec3(3, 0, 0))}));
    m.draw(m.transformed(drilled, {translate(Vec3(0, 3, 0))}));

    // Coincident faces: a block minus its own upper half, a cone capped flush with a box.
    int32_t halved = m.csg(scene::CsgOp::Difference, m.box(Vec3(-1), Vec3(1)), m.box(Vec3(-1, 0, -1), Vec3(1, 1, 1)));
    m.draw(m.transformed(halved, {translate(Vec3(0, -3, 0))}));
    scene::ConeShape cone{Vec3(0, -1, 0), 0.8, Vec3(0, 1, 0), 0.3, false};
    int32_t flush = m.csg(scene::CsgOp::Intersection, m.entity(cone), m.box(Vec3(-1), Vec3(1)));
    m.draw(m.transformed(flush, {translate(Vec3(3, -3, 0))}));
    return m.desc;
}

std::unique_ptr<RenderScene> build(const scene::SceneDesc& desc) {
    std::string error;
    auto scene = buildRenderScene(desc, error);
    REQUIRE(scene);
    return scene;
}

using CrossingSet = std::vector<std::pair<double, int32_t>>;

CrossingSet crossings(const RenderScene& scene, const Ray& ray, QueryScratch& scratch, RayStats& stats) {
    CrossingSet out;
    scene.forEachCrossing(ray, kInfinity, {}, scratch, stats, [&](const Hit& hit) {
        out.emplace_back(hit.t, hit.primitive);
        return true;
    });
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST_CASE("CSG of convex solids matches the general merge on every ray", "[csg]") {
    const scene::SceneDesc desc = convexCsgScene();
    std::unique_ptr<RenderScene> fast = build(desc);
    std::unique_ptr<RenderScene> general = build(desc);
    int convexNodes = 0;
    for (CsgTreeNode& node : general->csgNodes) {
        convexNodes += node.convex && node.kind != CsgNodeKind::Leaf;
        node.convex = false;
    }
    REQUIRE(convexNodes >= 6); // the shortcut is really taken

    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> inBox(-5, 5), axis(-1, 1);
    QueryScratch scratchA, scratchB;
    RayStats statsA, statsB;
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray{Vec3(inBox(random), inBox(random), inBox(random)), Vec3(axis(random), axis(random), axis(random))};
        if (i % 4 == 0) {
            // Axis-parallel rays meet coincident faces exactly.
            ray.dir = Vec3(0);
            ray.dir[i / 4 % 3] = i % 8 == 0 ? 1 : -1;
        }
        if (glm::length(ray.dir) < 1e-3) continue;
        ray.dir = glm::normalize(ray.dir);
        Hit a, b;
        bool foundA = fast->intersect(ray, kInfinity, a, scratchA, statsA);
        bool foundB = general->intersect(ray, kInfinity, b, scratchB, statsB);
        REQUIRE(foundA == foundB);
        if (foundA) {
            ++hits;
            REQUIRE(a.t == b.t);
            REQUIRE(a.primitive == b.primitive);
            REQUIRE(a.crossing.part == b.crossing.part);
            REQUIRE(a.flipNormal == b.flipNormal);
        }
        REQUIRE(crossings(*fast, ray, scratchA, statsA) == crossings(*general, ray, scratchB, statsB));
    }
    CHECK(hits > 2000);
}
