// The Geometry variant: construction from shapes, dispatch, and nearest-crossing queries.
#include "geometry_test_support.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

TEST_CASE("geometry: makeGeometry covers the plain shapes only") {
    CHECK(holds<SphereGeometry>(*makeGeometry(scene::SphereShape{{0, 0, 0}, 1})));
    CHECK(holds<BoxGeometry>(*makeGeometry(scene::BoxShape{{0, 0, 0}, {1, 1, 1}})));
    CHECK(holds<PlaneGeometry>(*makeGeometry(scene::PlaneShape{})));
    CHECK(holds<CylinderGeometry>(*makeGeometry(scene::CylinderShape{})));
    CHECK(holds<ConeGeometry>(*makeGeometry(scene::ConeShape{})));
    CHECK(holds<TorusGeometry>(*makeGeometry(scene::TorusShape{})));
    CHECK(holds<DiscGeometry>(*makeGeometry(scene::DiscShape{})));
    CHECK(holds<QuadGeometry>(*makeGeometry(scene::QuadShape{})));
    CHECK(holds<TriangleGeometry>(*makeGeometry(scene::TriangleShape{})));
    CHECK(holds<SuperellipsoidGeometry>(
        *makeGeometry(scene::SuperellipsoidShape{})));
    CHECK_FALSE(makeGeometry(scene::MeshShape{"a.obj", ""}));
    CHECK_FALSE(makeGeometry(scene::CsgNode{}));
    CHECK_FALSE(makeGeometry(scene::TransformNode{}));
    CHECK_FALSE(makeGeometry(scene::GroupNode{}));
}

TEST_CASE(
    "geometry: a smooth triangle interpolates its corners' directions, whatever their length") {
    scene::SmoothTriangleShape s =
        scene::smoothTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {3, 0, 0}, {0, 1, 0});
    Geometry g = *makeGeometry(s);
    CHECK_FALSE(isSolid(g));
    Ray ray{{0.5, 0.25, -3}, {0, 0, 1}};
    CrossingList list;
    crossLine(g, ray, list);
    REQUIRE(list.count == 1);
    SurfacePoint sp = surfaceAt(g, ray, list[0]);
    // Barycentric weights 0.25, 0.5, 0.25 of the unit corner normals.
    const Vec3 expected = glm::normalize(Vec3(0.5, 0.25, -0.25));
    CHECK(sp.shadingNormal.x == Approx(expected.x));
    CHECK(sp.shadingNormal.y == Approx(expected.y));
    CHECK(sp.shadingNormal.z == Approx(expected.z));
    CHECK(sp.normal.z == Approx(-1)); // the face turned toward the corner normals' side
    CHECK(sp.uv.x == Approx(0.5));
}

TEST_CASE("geometry: a polygon's loops are read by the even-odd rule") {
    // A 2×2 square in the x-z plane with a 1×1 hole, written as POV-Ray writes it.
    scene::PolygonShape s{{{0, 0, 0},
                           {2, 0, 0},
                           {2, 0, 2},
                           {0, 0, 2},
                           {0, 0, 0},
                           {0.5, 0, 0.5},
                           {1.5, 0, 0.5},
                           {1.5, 0, 1.5},
                           {0.5, 0, 1.5}}};
    Geometry g = *makeGeometry(s);
    CHECK_FALSE(isSolid(g));
    auto crossings = [&](double x, double z) {
        CrossingList list;
        crossLine(g, {{x, 3, z}, {0, -2, 0}}, list);
        return list.count;
    };
    CHECK(crossings(0.25, 0.25) == 1); // the frame
    CHECK(crossings(1.75, 1.0) == 1);
    CHECK(crossings(1.0, 1.0) == 0); // the hole
    CHECK(crossings(2.5, 1.0) == 0); // outside
    CrossingList list;
    Ray ray{{0.25, 3, 1.0}, {0, -2, 0}};
    crossLine(g, ray, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].t == Approx(1.5));
    SurfacePoint sp = surfaceAt(g, ray, list[0]);
    // The first loop runs x, then z: by the right-hand rule its normal is −y.
    CHECK(sp.normal.y == Approx(-1));
    CHECK(geometryBounds(g).contains(Vec3(2, 0, 2)));
    // Fewer than three points, or no area, draw nothing.
    CHECK(geometryBounds(*makeGeometry(scene::PolygonShape{{{0, 0, 0}, {1, 0, 0}}})).empty());
    CHECK(geometryBounds(*makeGeometry(scene::PolygonShape{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}))
              .empty());
}

TEST_CASE("geometry: solidity follows the spec") {
    CHECK(isSolid(*makeGeometry(scene::SphereShape{{0, 0, 0}, 1})));
    CHECK(isSolid(*makeGeometry(scene::BoxShape{})));
    CHECK(isSolid(*makeGeometry(scene::PlaneShape{})));
    CHECK(isSolid(*makeGeometry(scene::CylinderShape{{0, 0, 0}, {0, 1, 0}, 1, false})));
    CHECK_FALSE(isSolid(*makeGeometry(scene::CylinderShape{{0, 0, 0}, {0, 1, 0}, 1, true})));
    CHECK(isSolid(*makeGeometry(scene::ConeShape{{0, 0, 0}, 1, {0, 1, 0}, 0, false})));
    CHECK_FALSE(isSolid(*makeGeometry(scene::ConeShape{{0, 0, 0}, 1, {0, 1, 0}, 0, true})));
    CHECK(isSolid(*makeGeometry(scene::TorusShape{})));
    CHECK_FALSE(isSolid(*makeGeometry(scene::DiscShape{})));
    CHECK_FALSE(isSolid(*makeGeometry(scene::QuadShape{})));
    CHECK_FALSE(isSolid(*makeGeometry(scene::TriangleShape{})));
    CHECK(isSolid(*makeGeometry(scene::SuperellipsoidShape{})));
    auto mesh = std::make_shared<MeshData>();
    CHECK_FALSE(isSolid(Geometry(MeshGeometry(std::make_shared<const TriangleMesh>(mesh)))));
}

TEST_CASE("geometry: the free functions dispatch to the primitive") {
    Geometry g = *makeGeometry(scene::SphereShape{{0, 0, 0}, 2});
    Bounds3 b = geometryBounds(g);
    CHECK(b.lo.x == Approx(-2));
    CHECK(b.hi.z == Approx(2));
    CHECK(b.contains(Vec3(2, 0, 0)));
    Ray ray{{0, 0, -5}, {0, 0, 1}};
    CrossingList list;
    list.count = 3; // stale contents are replaced
    crossLine(g, ray, list);
    REQUIRE(list.count == 2);
    SurfacePoint sp = surfaceAt(g, ray, list[0]);
    CHECK(sp.point == Vec3(0, 0, -2));
    CHECK(geometryBounds(*makeGeometry(scene::PlaneShape{})).lo.y == -kInfinity);
    CHECK(geometryBounds(*makeGeometry(scene::TorusShape{{0, 0, 0}, 2, 0.5, {0, 1, 0}})).hi.y ==
          Approx(0.5));
    CHECK(geometryBounds(*makeGeometry(scene::TorusShape{{0, 0, 0}, 2, 0.5, {0, 1, 0}})).hi.x ==
          Approx(2.5));
}

TEST_CASE("geometry: firstCrossingIn takes the first crossing strictly inside the range") {
    // Two boxes' worth of crossings: a box crossed at t = -1 and t = 2, behind its origin and
    // ahead; a second line through it ahead only.
    const Geometry box(BoxGeometry({{-1, -1, -1}, {2, 1, 1}}));
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    Crossing c{};
    REQUIRE(firstCrossingIn(box, ray, 0, kInfinity, c));
    CHECK(c.t == 2);
    CHECK(c.part == 1);
    REQUIRE(firstCrossingIn(box, ray, -2, kInfinity, c));
    CHECK(c.t == -1);
    CHECK_FALSE(firstCrossingIn(box, ray, 2, kInfinity, c)); // strictly after tMin
    CHECK_FALSE(firstCrossingIn(box, ray, -1, 2, c));        // strictly before tMax
    CHECK_FALSE(firstCrossingIn(box, ray, 5, 100, c));
    REQUIRE(firstCrossingIn(box, ray, -kInfinity, 0, c));
    CHECK(c.t == -1);
    CHECK_FALSE(firstCrossingIn(box, Ray{{0, 5, 0}, {1, 0, 0}}, 0, kInfinity, c));
}

TEST_CASE("geometry: every primitive's bounds contain its random hits") {
    Random rng(51);
    std::vector<Geometry> shapes;
    shapes.push_back(*makeGeometry(scene::SphereShape{{1, 2, 3}, 1.5}));
    shapes.push_back(*makeGeometry(scene::BoxShape{{-1, 0, 2}, {3, 1, -1}}));
    shapes.push_back(*makeGeometry(scene::CylinderShape{{0, 0, 0}, {1, 2, 3}, 0.7, false}));
    shapes.push_back(*makeGeometry(scene::ConeShape{{0, 0, 0}, 0.2, {-1, 2, 1}, 1.1, false}));
    shapes.push_back(*makeGeometry(scene::TorusShape{{1, 1, 1}, 2, 0.3, {1, 1, 0}}));
    shapes.push_back(*makeGeometry(scene::DiscShape{{0, 1, 0}, {1, 1, 1}, 2, 0.5}));
    shapes.push_back(*makeGeometry(scene::QuadShape{{0, 0, 0}, {1, 2, 0}, {0, 1, 3}}));
    shapes.push_back(*makeGeometry(scene::TriangleShape{{0, 0, 0}, {1, 2, 0}, {0, 1, 3}}));
    shapes.push_back(*makeGeometry(scene::SuperellipsoidShape{0.05, 0.05}));
    shapes.push_back(*makeGeometry(scene::SuperellipsoidShape{3, 0.2}));
    for (const Geometry& g : shapes) {
        Bounds3 b = geometryBounds(g);
        REQUIRE(b.finite());
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            Ray ray = rng.lineThrough(
                b.centroid() + 0.5 * b.extent() *
                                   Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)),
                10);
            CrossingList list;
            crossLine(g, ray, list);
            for (int k = 0; k < list.count; ++k) {
                ++hits;
                // The exact surface is inside the bounds, so the point is, to its error bound.
                SurfacePoint sp = surfaceAt(g, ray, list[k]);
                CHECK(Bounds3{b.lo - sp.pointError, b.hi + sp.pointError}.contains(sp.point));
            }
        }
        CHECK(hits > 100);
    }
}

TEST_CASE("geometry: no direction or degenerate shapes give no crossings and no NaN") {
    std::vector<Geometry> shapes;
    shapes.push_back(*makeGeometry(scene::SphereShape{{0, 0, 0}, 1}));
    shapes.push_back(*makeGeometry(scene::BoxShape{{-1, -1, -1}, {1, 1, 1}}));
    shapes.push_back(*makeGeometry(scene::CylinderShape{{0, -1, 0}, {0, 1, 0}, 1, false}));
    shapes.push_back(*makeGeometry(scene::ConeShape{{0, -1, 0}, 1, {0, 1, 0}, 0, true}));
    shapes.push_back(*makeGeometry(scene::TorusShape{{0, 0, 0}, 1, 0.5, {0, 1, 0}}));
    shapes.push_back(*makeGeometry(scene::DiscShape{{0, 0, 0}, {0, 1, 0}, 1, 0}));
    shapes.push_back(*makeGeometry(scene::QuadShape{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}));
    shapes.push_back(*makeGeometry(scene::TriangleShape{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}));
    shapes.push_back(*makeGeometry(scene::SuperellipsoidShape{0.5, 3}));
    for (const Geometry& g : shapes) {
        CrossingList list;
        crossLine(g, {{0, 0, 0}, {0, 0, 0}}, list);
        CHECK(list.count == 0);
    }
    std::vector<Geometry> degenerate;
    degenerate.push_back(*makeGeometry(scene::SphereShape{{0, 0, 0}, -1}));
    degenerate.push_back(*makeGeometry(scene::BoxShape{{1, 1, 1}, {1, 1, 1}}));
    degenerate.push_back(*makeGeometry(scene::PlaneShape{{0, 0, 0}, {0, 0, 0}}));
    degenerate.push_back(*makeGeometry(scene::CylinderShape{{0, 0, 0}, {0, 0, 0}, 1, false}));
    degenerate.push_back(*makeGeometry(scene::ConeShape{{0, 0, 0}, 0, {0, 1, 0}, 0, false}));
    degenerate.push_back(*makeGeometry(scene::TorusShape{{0, 0, 0}, 1, 1, {0, 0, 0}}));
    degenerate.push_back(*makeGeometry(scene::DiscShape{{0, 0, 0}, {0, 0, 0}, 1, 0}));
    degenerate.push_back(*makeGeometry(scene::QuadShape{{0, 0, 0}, {0, 0, 0}, {0, 0, 1}}));
    degenerate.push_back(*makeGeometry(scene::TriangleShape{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
    degenerate.push_back(*makeGeometry(scene::SuperellipsoidShape{0, 1}));
    Random rng(52);
    for (const Geometry& g : degenerate) {
        for (int i = 0; i < 200; ++i) {
            CrossingList list;
            crossLine(g, rng.lineThrough(rng.inBox(0.5), 3), list);
            CHECK(list.count == 0);
            CHECK_FALSE(list.startsInside);
        }
    }
}
