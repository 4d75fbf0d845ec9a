// Disc, quad and triangle crossings, surface points and their error bounds.
#include "geometry_test_support.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

SurfaceFn planeThrough(const Vec3& point, const Vec3& normal) {
    LVec n(normal);
    n = (1 / length(n)) * n;
    LVec q(point);
    return [=](const LVec& p) { return dot(n, p - q); };
}

/// Checks a random line's crossing with a planar shape: count, side of normal, bound.
template <class G>
void checkPlanarHit(const G& g, const Ray& ray, const SurfaceFn& plane,
                    const Vec3& expectedNormal) {
    CrossingList list;
    g.crossLine(ray, list);
    REQUIRE(list.count == 1);
    CHECK_FALSE(list.startsInside);
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    checkUnit(sp.normal);
    CHECK(glm::length(sp.normal - glm::normalize(expectedNormal)) < 1e-12);
    CHECK(sp.shadingNormal == sp.normal);
    CHECK(g.bounds().contains(sp.point));
    CHECK((sp.uv.x >= 0 && sp.uv.x <= 1 && sp.uv.y >= 0 && sp.uv.y <= 1));
    if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) return;
    checkBoundContainsExact(sp, ray, plane, list[0].t);
}

} // namespace

TEST_CASE("disc: hits inside, misses outside and in the hole") {
    DiscGeometry g({{0, 1, 0}, {0, 3, 0}, 2, 0.5});
    CHECK_FALSE(g.solid());
    CrossingList list;
    Ray down{{1, 5, 0}, {0, -2, 0}};
    g.crossLine(down, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].t == 2);
    SurfacePoint sp = g.surfaceAt(down, list[0]);
    CHECK(sp.point == Vec3(1, 1, 0));
    CHECK(sp.normal == Vec3(0, 1, 0));
    CHECK(sp.uv.y == 0.5);
    CHECK(sp.uv.x == 0);                           // +x is the frame's u axis for normal +y
    g.crossLine({{0.25, 5, 0}, {0, -1, 0}}, list); // in the hole
    CHECK(list.count == 0);
    g.crossLine({{2.5, 5, 0}, {0, -1, 0}}, list); // outside
    CHECK(list.count == 0);
    g.crossLine({{1, -5, 0}, {0, 1, 0}}, list); // from behind: still one crossing
    REQUIRE(list.count == 1);
    g.crossLine({{1, 5, 0}, {0, 1, 0}}, list); // moving away: the crossing is behind
    REQUIRE(list.count == 1);
    CHECK(list[0].t == -4);
    g.crossLine({{-5, 1, 0}, {1, 0, 0}}, list); // in its plane: parallel
    CHECK(list.count == 0);
}

TEST_CASE("disc: degenerate ones draw nothing") {
    CrossingList list;
    DiscGeometry zero({{0, 0, 0}, {0, 1, 0}, 0, 0});
    zero.crossLine({{0, 1, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
    DiscGeometry allHole({{0, 0, 0}, {0, 1, 0}, 1, 1});
    allHole.crossLine({{0.99, 1, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
}

TEST_CASE("disc: random lines") {
    Random rng(41);
    for (int i = 0; i < 2000; ++i) {
        scene::DiscShape s{rng.inBox(5), rng.unit() * rng.uniform(0.5, 3), rng.uniform(0.5, 3), 0};
        DiscGeometry g(s);
        Vec3 n = glm::normalize(s.normal);
        Vec3 inPlane = glm::normalize(glm::cross(n, rng.unit()));
        Ray ray = rng.lineThrough(s.center + inPlane * s.radius * rng.uniform(0, 0.99),
                                  rng.uniform(0.1, 30));
        checkPlanarHit(g, ray, planeThrough(s.center, s.normal), s.normal);
    }
}

TEST_CASE("quad: the parallelogram's inside, edges and UV") {
    QuadGeometry g({{0, 0, 0}, {2, 0, 0}, {1, 0, -1}}); // normal (2,0,0)×(1,0,−1) = (0,2,0)
    CrossingList list;
    Ray down{{1.5, 3, -0.5}, {0, -1, 0}};
    g.crossLine(down, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].t == 3);
    SurfacePoint sp = g.surfaceAt(down, list[0]);
    CHECK(sp.normal == Vec3(0, 1, 0));
    CHECK(sp.uv.x == Approx(0.5));
    CHECK(sp.uv.y == Approx(0.5));
    g.crossLine({{0.2, 3, -0.5}, {0, -1, 0}}, list); // outside the slanted edge
    CHECK(list.count == 0);
    g.crossLine({{2, 3, 0}, {0, -1, 0}}, list); // exactly on a corner: inclusive
    CHECK(list.count == 1);
    g.crossLine({{-1, 0, -0.5}, {1, 0, 0}}, list); // in its plane
    CHECK(list.count == 0);
    QuadGeometry flat({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    flat.crossLine({{0.5, 1, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
    CHECK(flat.bounds().empty());
}

TEST_CASE("quad: random lines") {
    Random rng(42);
    for (int i = 0; i < 2000; ++i) {
        scene::QuadShape s{rng.inBox(5), rng.inBox(3), rng.inBox(3)};
        if (glm::length(glm::cross(s.edgeA, s.edgeB)) < 0.5) continue;
        QuadGeometry g(s);
        Vec3 target =
            s.corner + rng.uniform(0.01, 0.99) * s.edgeA + rng.uniform(0.01, 0.99) * s.edgeB;
        Ray ray = rng.lineThrough(target, rng.uniform(0.1, 30));
        checkPlanarHit(g, ray, planeThrough(s.corner, glm::cross(s.edgeA, s.edgeB)),
                       glm::cross(s.edgeA, s.edgeB));
    }
}

TEST_CASE("triangle: right-hand normal, barycentric UV, misses and parallel lines") {
    TriangleGeometry g({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CrossingList list;
    Ray ray{{0.25, 0.5, 2}, {0, 0, -4}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].t == 0.5);
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.normal == Vec3(0, 0, 1));
    CHECK(sp.point == Vec3(0.25, 0.5, 0));
    CHECK(sp.uv.x == Approx(0.25));
    CHECK(sp.uv.y == Approx(0.5));
    Vec3 b = g.barycentrics(ray, list[0]);
    CHECK(b.x == Approx(0.25));
    g.crossLine({{0.6, 0.6, 2}, {0, 0, -1}}, list); // beyond the hypotenuse
    CHECK(list.count == 0);
    g.crossLine({{0.25, 0.25, -2}, {0, 0, 1}}, list); // from behind
    CHECK(list.count == 1);
    g.crossLine({{0.25, 0.25, 2}, {0, 0, 1}}, list); // moving away
    REQUIRE(list.count == 1);
    CHECK(list[0].t == -2);
    g.crossLine({{-1, 0.25, 0}, {1, 0, 0}}, list); // in its plane
    CHECK(list.count == 0);
    g.crossLine({{-1, 0.25, 1}, {1, 0, 0}}, list); // parallel above
    CHECK(list.count == 0);
    TriangleGeometry collinear({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
    collinear.crossLine({{1, 1, 0}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
    CHECK(collinear.bounds().empty());
}

TEST_CASE("triangle: lines through a shared edge or vertex never slip through") {
    // A flat fan of triangles around a vertex (flat, so no edge is a silhouette): every line
    // through a shared edge or the shared vertex hits at least one.
    Vec3 centre(0.1, 0.2, 0.3);
    std::vector<TriangleGeometry> fan;
    const int n = 7;
    std::vector<Vec3> rim;
    for (int i = 0; i < n; ++i)
        rim.push_back(centre + Vec3(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0));
    for (int i = 0; i < n; ++i)
        fan.emplace_back(scene::TriangleShape{centre, rim[size_t(i)], rim[size_t((i + 1) % n)]});
    Random rng(43);
    for (int k = 0; k < 5000; ++k) {
        int e = k % n;
        Vec3 target =
            k % 10 == 0 ? centre : centre + rng.uniform(0, 0.99) * (rim[size_t(e)] - centre);
        Ray ray = rng.lineThrough(target, rng.uniform(0.5, 20));
        int hits = 0;
        for (const TriangleGeometry& t : fan) {
            CrossingList list;
            t.crossLine(ray, list);
            hits += list.count;
        }
        CHECK(hits >= 1);
    }
}

TEST_CASE("triangle: random lines") {
    Random rng(44);
    for (int i = 0; i < 2000; ++i) {
        scene::TriangleShape s{rng.inBox(5), rng.inBox(5), rng.inBox(5)};
        Vec3 n = glm::cross(s.b - s.a, s.c - s.a);
        if (glm::length(n) < 0.5) continue;
        TriangleGeometry g(s);
        double u = rng.uniform(0.01, 0.98), v = rng.uniform(0.01, 0.99 - u);
        Ray ray = rng.lineThrough(s.a + u * (s.b - s.a) + v * (s.c - s.a), rng.uniform(0.1, 30));
        checkPlanarHit(g, ray, planeThrough(s.a, n), n);
        CrossingList list;
        g.crossLine(ray, list);
        SurfacePoint sp = g.surfaceAt(ray, list[0]);
        CHECK(sp.uv.x == Approx(u).margin(1e-9));
        CHECK(sp.uv.y == Approx(v).margin(1e-9));
    }
}
