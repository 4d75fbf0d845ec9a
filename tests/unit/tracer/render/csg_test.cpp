// CSG on crossing lists: difference, intersection, union, nesting, transforms, coincident faces.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

struct Probe {
    std::unique_ptr<RenderScene> scene;
    QueryScratch scratch;
    RayStats stats;

    explicit Probe(const scene::SceneDesc& desc) {
        std::string error;
        scene = buildRenderScene(desc, error);
        REQUIRE(scene);
    }
    bool hit(const Ray& ray, Hit& hit) { return scene->intersect(ray, kInfinity, hit, scratch, stats); }
    int crossings(const Ray& ray) {
        int n = 0;
        scene->forEachCrossing(ray, kInfinity, {}, scratch, stats,
                               [&](const Hit&) { return ++n, true; });
        return n;
    }
};

} // namespace

TEST_CASE("CSG difference removes the subtracted solid and shows its cut face", "[csg]") {
    SceneMaker m;
    int32_t red = m.colored(1, 0, 0);
    int32_t blue = m.colored(0, 0, 1);
    int32_t box = m.box(Vec3(-1), Vec3(1), red);
    int32_t ball = m.sphere(Vec3(-1, 0, 0), 0.5, blue);
    m.draw(m.csg(scene::CsgOp::Difference, box, ball));
    Probe probe(m.desc);

    Hit hit;
    // Along the x axis the box's face at x = -1 lies inside the ball: the hit is the cut face.
    REQUIRE(probe.hit({Vec3(-5, 0, 0), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(4.5));
    SurfaceInteraction si = probe.scene->interaction({Vec3(-5, 0, 0), Vec3(1, 0, 0)}, hit);
    CHECK(si.material == blue);
    CHECK(si.normal.x == Approx(-1)); // outward of the result, not of the ball
    // Away from the ball the box face is intact.
    REQUIRE(probe.hit({Vec3(-5, 0.8, 0.8), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(4));
    CHECK(probe.scene->interaction({Vec3(-5, 0.8, 0.8), Vec3(1, 0, 0)}, hit).material == red);
    // A ray that only meets the ball outside the box sees nothing.
    CHECK_FALSE(probe.hit({Vec3(-1.4, 5, 0), Vec3(0, -1, 0)}, hit));
}

TEST_CASE("CSG intersection keeps only the common part", "[csg]") {
    SceneMaker m;
    int32_t a = m.sphere(Vec3(-0.5, 0, 0), 1);
    int32_t b = m.sphere(Vec3(0.5, 0, 0), 1);
    m.draw(m.csg(scene::CsgOp::Intersection, a, b));
    Probe probe(m.desc);
    Hit hit;
    REQUIRE(probe.hit({Vec3(-5, 0, 0), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(4.5)); // b's near side at x = -0.5
    CHECK(probe.crossings({Vec3(-5, 0, 0), Vec3(1, 0, 0)}) == 2);
    CHECK_FALSE(probe.hit({Vec3(-1.2, 5, 0), Vec3(0, -1, 0)}, hit));
}

TEST_CASE("CSG union keeps its interior surfaces", "[csg]") {
    SceneMaker m;
    int32_t a = m.sphere(Vec3(-0.5, 0, 0), 1);
    int32_t b = m.sphere(Vec3(0.5, 0, 0), 1);
    int32_t c = m.box(Vec3(-3, -3, -3), Vec3(3, 3, -2.5));
    // (a + b) − c forces the union through the CSG evaluator rather than flattening it.
    m.draw(m.csg(scene::CsgOp::Difference, m.csg(scene::CsgOp::Union, a, b), c));
    Probe probe(m.desc);
    CHECK(probe.crossings({Vec3(-5, 0, 0), Vec3(1, 0, 0)}) == 4);
}

TEST_CASE("CSG merge keeps only the outer surface, drawn alone or inside other CSG", "[csg]") {
    SceneMaker m;
    int32_t a = m.sphere(Vec3(-0.5, 0, 0), 1);
    int32_t b = m.sphere(Vec3(0.5, 0, 0), 1);
    int32_t c = m.sphere(Vec3(2.0, 0, 0), 0.25); // apart from both: its surface stays
    int32_t merged = m.csg(scene::CsgOp::Merge, m.csg(scene::CsgOp::Merge, a, b), c);
    m.draw(merged);
    Probe probe(m.desc);
    CHECK(probe.crossings({Vec3(-5, 0, 0), Vec3(1, 0, 0)}) == 4); // -1.5, 1.5, then c's two
    Hit hit;
    // A line through b only, missing a, still meets the merge.
    REQUIRE(probe.hit({Vec3(1.2, -5, 0), Vec3(0, 1, 0)}, hit));
    CHECK(hit.t == Approx(5 - std::sqrt(1 - 0.7 * 0.7)));
    // From inside the overlap: the first surface is the far side of the merge, not b's inside.
    REQUIRE(probe.hit({Vec3(0, 0, 0), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(1.5));

    SceneMaker n;
    int32_t box = n.box(Vec3(-3, -3, -3), Vec3(3, 3, -2.5));
    int32_t pair =
        n.csg(scene::CsgOp::Merge, n.sphere(Vec3(-0.5, 0, 0), 1), n.sphere(Vec3(0.5, 0, 0), 1));
    n.draw(n.csg(scene::CsgOp::Difference, pair, box));
    Probe nested(n.desc);
    CHECK(nested.crossings({Vec3(-5, 0, 0), Vec3(1, 0, 0)}) == 2);
}

TEST_CASE("CSG inverse: the outside of a solid, bounded by its surface facing inward", "[csg]") {
    SceneMaker m;
    int32_t box = m.box(Vec3(-1), Vec3(1));
    int32_t ball = m.sphere(Vec3(1, 0, 0), 0.5);
    // box ^ inverse(ball) is box − ball.
    m.draw(m.csg(scene::CsgOp::Intersection, box, m.entity(scene::InverseNode{ball})));
    Probe probe(m.desc);
    Hit hit;
    const Ray ray{Vec3(5, 0, 0), Vec3(-1, 0, 0)};
    REQUIRE(probe.hit(ray, hit));
    CHECK(hit.t == Approx(4.5));
    SurfaceInteraction si = probe.scene->interaction(ray, hit);
    CHECK(si.normal.x == Approx(1)); // toward the ray: out of the result, into the ball
    CHECK(probe.crossings(ray) == 2);

    // Drawn alone, an inverse shows its solid's surface with the normals turned inward.
    SceneMaker alone;
    alone.draw(alone.entity(scene::InverseNode{alone.sphere(Vec3(0), 1)}));
    Probe lone(alone.desc);
    const Ray in{Vec3(0, 0, -5), Vec3(0, 0, 1)};
    REQUIRE(lone.hit(in, hit));
    CHECK(hit.t == Approx(4));
    CHECK(lone.scene->interaction(in, hit).normal.z == Approx(1));
    // The inverse of nothing is all space: no surface, and an intersection with it is unchanged.
    SceneMaker none;
    int32_t empty = none.csg(scene::CsgOp::Intersection, none.sphere(Vec3(-3, 0, 0), 1),
                             none.sphere(Vec3(3, 0, 0), 1));
    none.draw(none.csg(scene::CsgOp::Intersection, none.box(Vec3(-1), Vec3(1)),
                       none.entity(scene::InverseNode{empty})));
    Probe all(none.desc);
    REQUIRE(all.hit({Vec3(-5, 0, 0), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(4));
}

TEST_CASE("CSG: coincident faces leave no slivers, even through different transforms", "[csg]") {
    SceneMaker m;
    int32_t outer = m.box(Vec3(-1), Vec3(1));
    // A square hole whose front and back faces coincide with the outer box's, built through
    // a scale and two translations so its face positions carry rounding differences.
    int32_t inner = m.transformed(m.box(Vec3(-1), Vec3(1)),
                                  {scale(Vec3(0.5, 0.5, 1)), translate(Vec3(0.1, 0.3, 0)), translate(Vec3(-0.1, -0.3, 0))});
    m.draw(m.csg(scene::CsgOp::Difference, outer, inner));
    Probe probe(m.desc);
    int throughHole = 0, onFace = 0;
    for (int i = 0; i <= 100; ++i) {
        for (int j = 0; j <= 100; ++j) {
            double x = -0.99 + 1.98 * i / 100, y = -0.99 + 1.98 * j / 100;
            if (std::abs(std::abs(x) - 0.5) < 1e-6 || std::abs(std::abs(y) - 0.5) < 1e-6) continue;
            Ray ray{Vec3(x, y, -5), Vec3(0, 0, 1)};
            Hit hit;
            bool inHole = std::abs(x) < 0.5 && std::abs(y) < 0.5;
            bool found = probe.hit(ray, hit);
            if (inHole) {
                // The hole's walls are parallel to the ray: nothing may be hit inside it.
                REQUIRE_FALSE(found);
                ++throughHole;
            } else {
                REQUIRE(found);
                REQUIRE(hit.t == Approx(4));
                ++onFace;
            }
        }
    }
    CHECK(throughHole > 2000);
    CHECK(onFace > 5000);
}

TEST_CASE("CSG: a cap flush with a face is cut cleanly (box minus cylinder)", "[csg]") {
    SceneMaker m;
    int32_t box = m.box(Vec3(-1, 0, -1), Vec3(1, 1, 1));
    int32_t drill = m.entity(scene::CylinderShape{Vec3(0, 0, 0), Vec3(0, 1, 0), 0.5, false});
    m.draw(m.csg(scene::CsgOp::Difference, box, drill));
    Probe probe(m.desc);
    Hit hit;
    // Looking down the drilled hole: nothing, not the box's top face nor the cylinder's cap.
    for (double x : {-0.4, -0.1, 0.0, 0.2, 0.45}) {
        REQUIRE_FALSE(probe.hit({Vec3(x, 5, 0.1), Vec3(0, -1, 0)}, hit));
    }
    // Looking at the top face beside the hole: the top face.
    REQUIRE(probe.hit({Vec3(0.7, 5, 0.7), Vec3(0, -1, 0)}, hit));
    CHECK(hit.t == Approx(4));
    // Looking up from below into the hole: nothing either (the bottom cap is flush too).
    REQUIRE_FALSE(probe.hit({Vec3(0.1, -5, 0.1), Vec3(0, 1, 0)}, hit));
    // A ray through the solid part crosses the drill's wall as a cut face of the drill.
    REQUIRE(probe.hit({Vec3(0.0, 0.5, 0.0), Vec3(1, 0, 0)}, hit));
    CHECK(hit.t == Approx(0.5));
    CHECK(probe.scene->interaction({Vec3(0.0, 0.5, 0.0), Vec3(1, 0, 0)}, hit).normal.x == Approx(-1));
}

TEST_CASE("CSG nests to any depth and on transformed operands", "[csg]") {
    SceneMaker m;
    // A box with 400 small holes subtracted one by one: ((box − s1) − s2) − …
    int32_t shape = m.box(Vec3(-10, -10, -0.2), Vec3(10, 10, 0.2));
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
            shape = m.csg(scene::CsgOp::Difference, shape, m.sphere(Vec3(-9.5 + i, -9.5 + j, 0), 0.3));
    // … then rotated as a whole, and intersected with a big sphere.
    int32_t rotated = m.transformed(shape, {rotate(Vec3(0, 0, 90))});
    m.draw(m.csg(scene::CsgOp::Intersection, rotated, m.sphere(Vec3(0), 8)));
    Probe probe(m.desc);
    Hit hit;
    CHECK_FALSE(probe.hit({Vec3(-0.5, -0.5, -5), Vec3(0, 0, 1)}, hit)); // a hole
    REQUIRE(probe.hit({Vec3(0, 0, -5), Vec3(0, 0, 1)}, hit));             // between holes
    CHECK(hit.t == Approx(4.8));
    CHECK_FALSE(probe.hit({Vec3(9, 0, -5), Vec3(0, 0, 1)}, hit)); // cut away by the big sphere
}

TEST_CASE("A clipped entity keeps its own surfaces inside the clipping solid, and no others", "[csg]") {
    SceneMaker m;
    int32_t red = m.colored(1, 0, 0);
    int32_t blue = m.colored(0, 0, 1);
    // The unit sphere cut by the half-space below y = 0.5: a bowl open at the top.
    int32_t ball = m.sphere(Vec3(0), 1, red);
    int32_t below = m.box(Vec3(-2), Vec3(2, 0.5, 2), blue);
    m.draw(m.csg(scene::CsgOp::Clip, ball, below));
    Probe probe(m.desc);
    Hit hit;
    // Down the axis: through the opening, onto the bowl's inside at its bottom.
    REQUIRE(probe.hit({Vec3(0, 5, 0), Vec3(0, -1, 0)}, hit));
    CHECK(hit.t == Approx(6));
    CHECK(probe.scene->interaction({Vec3(0, 5, 0), Vec3(0, -1, 0)}, hit).material == red);
    CHECK(probe.crossings({Vec3(0, 5, 0), Vec3(0, -1, 0)}) == 1);
    // Across below the cut: both walls; above it: nothing, not even the box's face.
    CHECK(probe.crossings({Vec3(-5, 0, 0), Vec3(1, 0, 0)}) == 2);
    CHECK_FALSE(probe.hit({Vec3(-5, 0.8, 0), Vec3(1, 0, 0)}, hit));
    // Where the box alone is: nothing of it is drawn.
    CHECK_FALSE(probe.hit({Vec3(1.5, 5, 1.5), Vec3(0, -1, 0)}, hit));
}
