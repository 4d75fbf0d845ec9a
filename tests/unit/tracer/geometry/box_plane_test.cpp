// Box and plane crossings, surface points and their error bounds.
#include "geometry_test_support.hpp"

#include <algorithm>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// The exact face plane of a box crossing, as a signed distance.
SurfaceFn boxFaceFn(const scene::BoxShape& b, uint32_t part) {
    int axis = int(part / 2);
    bool high = part % 2 == 1;
    LD face = high ? std::max(b.cornerA[axis], b.cornerB[axis])
                   : std::min(b.cornerA[axis], b.cornerB[axis]);
    return [=](const LVec& p) { return high ? p[axis] - face : face - p[axis]; };
}

bool insideBox(const scene::BoxShape& b, const LVec& p) {
    for (int i = 0; i < 3; ++i) {
        LD lo = std::min(b.cornerA[i], b.cornerB[i]), hi = std::max(b.cornerA[i], b.cornerB[i]);
        if (p[i] < lo || p[i] > hi) return false;
    }
    return true;
}

SurfaceFn planeFn(const scene::PlaneShape& s) {
    LVec n(s.normal);
    LD len = length(n);
    return [=](const LVec& p) { return dot(n, p - LVec(s.position)) / len; };
}

} // namespace

TEST_CASE("box: a line through the middle crosses the faces it meets") {
    BoxGeometry g({{1, 1, 1}, {-1, -1, -1}}); // corners in any order
    CrossingList list;
    Ray ray{{-5, 0, 0}, {1, 0, 0}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 2);
    CHECK_FALSE(list.startsInside);
    CHECK(list[0].t == 4);
    CHECK(list[0].part == 0);
    CHECK(list[1].t == 6);
    CHECK(list[1].part == 1);
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.point == Vec3(-1, 0, 0));
    CHECK(sp.normal == Vec3(-1, 0, 0));
    CHECK(sp.pointError.x == 0);
    CHECK(sp.uv == Vec2(0.5, 0.5));
    sp = g.surfaceAt(ray, list[1]);
    CHECK(sp.normal == Vec3(1, 0, 0));

    g.crossLine({{0.5, 0.25, 9}, {0, 0, -2}}, list); // from +z, non-unit direction
    REQUIRE(list.count == 2);
    CHECK(list[0].t == 4);
    CHECK(list[0].part == 5);
    CHECK(list[1].t == 5);
    CHECK(list[1].part == 4);
    sp = g.surfaceAt({{0.5, 0.25, 9}, {0, 0, -2}}, list[0]);
    CHECK(sp.uv.x == 0.75);  // face z: u along x
    CHECK(sp.uv.y == 0.625); // v along y
}

TEST_CASE("box: from inside and past the box") {
    BoxGeometry g({{0, 0, 0}, {2, 4, 6}});
    CrossingList list;
    g.crossLine({{1, 1, 1}, {0, 1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == -1);
    CHECK(list[1].t == 3);
    Crossing c{};
    REQUIRE(firstCrossingIn(Geometry(g), Ray{{1, 1, 1}, {0, 1, 0}}, 0, kInfinity, c));
    CHECK(c.part == 3);
    g.crossLine({{1, 10, 1}, {0, 1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[1].t == -6);
    CHECK_FALSE(firstCrossingIn(Geometry(g), Ray{{1, 10, 1}, {0, 1, 0}}, 0, kInfinity, c));
}

TEST_CASE("box: a line in a face plane or along an edge never crosses once") {
    BoxGeometry g({{-1, -1, -1}, {1, 1, 1}});
    CrossingList list;
    g.crossLine({{-5, 1, 0}, {1, 0, 0}}, list); // in the plane y = 1
    CHECK(list.count == 2);
    g.crossLine({{-5, 1, 1}, {1, 0, 0}}, list); // along an edge
    CHECK(list.count == 2);
    g.crossLine({{-5, std::nextafter(1.0, 2.0), 0}, {1, 0, 0}}, list); // just above
    CHECK(list.count == 0);
    g.crossLine({{-3, -1, 0}, {1, 1, 0}}, list); // through the edge (−1, 1) only: grazing
    CHECK(list.count % 2 == 0);
    g.crossLine({{-2, 0, 0}, {1, 1, 1}}, list); // through the corner (−1, 1, 1)
    CHECK(list.count % 2 == 0);
    g.crossLine({{5, 5, 0}, {0, 0, 1}}, list); // parallel to two slabs, outside
    CHECK(list.count == 0);
    g.crossLine({{0, 0, 0}, {0, 0, 0}}, list); // no direction at all
    CHECK(list.count == 0);
}

TEST_CASE("box: zero extent draws nothing") {
    BoxGeometry g({{0, 0, 0}, {1, 0, 1}});
    CrossingList list;
    g.crossLine({{0.5, -5, 0.5}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    CHECK(g.bounds().empty());
}

TEST_CASE("box: random lines alternate, and hits are bounded and on their face") {
    Random rng(11);
    for (int i = 0; i < 3000; ++i) {
        Vec3 a = rng.inBox(5),
             b = a + Vec3(rng.uniform(0.01, 4), rng.uniform(0.01, 4), rng.uniform(0.01, 4));
        scene::BoxShape s{a, b};
        BoxGeometry g(s);
        Vec3 target = a + (b - a) * Vec3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1));
        Ray ray = rng.lineThrough(target, rng.uniform(0.1, 30));
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 2);
        checkAlternates(
            list, ray, [&](const LVec& p) { return insideBox(s, p); }, true);
        for (int k = 0; k < 2; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            int axis = int(list[k].part / 2);
            CHECK(std::abs(sp.normal[axis]) == 1);
            CHECK(glm::dot(sp.normal, ray.dir) * (k == 0 ? -1 : 1) >= 0);
            CHECK(g.bounds().contains(sp.point));
            CHECK((sp.uv.x >= 0 && sp.uv.x <= 1 && sp.uv.y >= 0 && sp.uv.y <= 1));
            if (std::abs(ray.dir[axis]) < 0.05 * glm::length(ray.dir)) continue;
            checkBoundContainsExact(sp, ray, boxFaceFn(s, list[k].part), list[k].t);
        }
    }
}

TEST_CASE("plane: one crossing, and the half-space behind the normal is inside") {
    PlaneGeometry g({{0, 2, 0}, {0, 1, 0}}); // non-unit normal
    CHECK(g.solid());
    CHECK(g.bounds().lo.x == -kInfinity);
    CHECK(g.bounds().hi.y == kInfinity);
    CrossingList list;
    Ray down{{0, 5, 0}, {0, -2, 0}};
    g.crossLine(down, list);
    REQUIRE(list.count == 1);
    CHECK_FALSE(list.startsInside);
    CHECK(list[0].t == 2);
    SurfacePoint sp = g.surfaceAt(down, list[0]);
    CHECK(sp.point == Vec3(0, 1, 0));
    CHECK(sp.normal == Vec3(0, 1, 0));

    g.crossLine({{0, -5, 0}, {0, 1, 0}}, list); // from behind
    REQUIRE(list.count == 1);
    CHECK(list.startsInside);
    CHECK(list[0].t == 6);
    g.crossLine({{0, 5, 0}, {0, 1, 0}}, list); // moving away: the crossing is behind
    REQUIRE(list.count == 1);
    CHECK(list.startsInside);
    CHECK(list[0].t == -4);
}

TEST_CASE("plane: a parallel line does not cross and is wholly on one side") {
    PlaneGeometry g({{0, 0, 1}, {0, 0, 3}});
    CrossingList list;
    g.crossLine({{0, 0, 4}, {1, 1, 0}}, list);
    CHECK(list.count == 0);
    CHECK_FALSE(list.startsInside);
    g.crossLine({{0, 0, 2}, {1, 1, 0}}, list);
    CHECK(list.count == 0);
    CHECK(list.startsInside);
    g.crossLine({{0, 0, 3}, {1, 0, 0}}, list); // in the plane: on the closed half-space
    CHECK(list.count == 0);
    CHECK(list.startsInside);
}

TEST_CASE("plane: UV are coordinates in the plane, not wrapped") {
    scene::PlaneShape s{{1, 1, 0}, {1, 2, 3}};
    PlaneGeometry g(s);
    Random rng(5);
    for (int i = 0; i < 100; ++i) {
        Ray ray = rng.lineThrough(s.position + Vec3(rng.uniform(-50, 50), -0, 0) * Vec3(1, -1, 1) +
                                      rng.uniform(-50, 50) * Vec3(0, 0, 1),
                                  10);
        CrossingList list;
        g.crossLine(ray, list);
        if (list.count != 1) continue;
        SurfacePoint sp = g.surfaceAt(ray, list[0]);
        CHECK(glm::length(sp.uv) == Approx(glm::length(sp.point - s.position)).epsilon(1e-9));
    }
}

TEST_CASE("plane: a zero normal draws nothing") {
    PlaneGeometry g({{0, 0, 0}, {0, 0, 0}});
    CrossingList list;
    g.crossLine({{0, 1, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
    CHECK_FALSE(list.startsInside);
}

TEST_CASE("plane: random lines give bounded hits and consistent sides") {
    Random rng(12);
    for (int i = 0; i < 3000; ++i) {
        scene::PlaneShape s{rng.unit() * rng.uniform(0.1, 10), rng.inBox(50)};
        PlaneGeometry g(s);
        Ray ray = rng.lineThrough(s.position + rng.inBox(20), rng.uniform(0.1, 100));
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count <= 1);
        checkAlternates(
            list, ray, [&](const LVec& p) { return planeFn(s)(p) <= 0; }, false);
        if (list.count == 0) continue;
        SurfacePoint sp = g.surfaceAt(ray, list[0]);
        checkUnit(sp.normal);
        CHECK(glm::dot(sp.normal, s.normal) > 0);
        if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
        checkBoundContainsExact(sp, ray, planeFn(s), list[0].t);
    }
}

TEST_CASE("plane: a distant hit keeps an error bound relative to its size") {
    PlaneGeometry g({{0, 1, 0}, {0, -1, 0}});
    Ray ray{{0, 1, 0}, glm::normalize(Vec3(1e6, -1, 3e5))};
    CrossingList list;
    g.crossLine(ray, list);
    REQUIRE(list.count == 1);
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.point.y == Approx(-1).margin(1e-9));
    CHECK(sp.pointError.x < 1e-8);
    CHECK(sp.pointError.y < 1e-8);
    checkBoundContainsExact(sp, ray, planeFn({{0, 1, 0}, {0, -1, 0}}), list[0].t);
}

// As for the sphere: a line nearly in the plane has an error in t of about 1/|n·d| times the
// distance it stands for, and the bound (hence a spawned ray's offset) covers only the latter.
TEST_CASE("plane: a grazing hit's bound is its distance from the surface") {
    scene::PlaneShape s{glm::normalize(Vec3(-0.2, 1, 0.1)), {0.4, -0.3, 0.2}};
    PlaneGeometry g(s);
    const Vec3 along = glm::normalize(glm::cross(s.normal, Vec3(1, 0.3, 0.2)));
    for (double cosine : {1e-3, 1e-5, 1e-7}) {
        Vec3 dir = glm::normalize(along - cosine * s.normal);
        Ray ray{s.position + Vec3(0.1, 0.2, -0.3) - 3.0 * dir, dir};
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 1);
        SurfacePoint sp = g.surfaceAt(ray, list[0]);
        INFO("n·d " << glm::dot(sp.normal, dir));
        double offset = glm::dot(absolute(sp.normal), sp.pointError);
        CHECK(offset < errorGamma(64) * (sumAbs(sp.point) + sumAbs(s.position)));
        checkBoundContainsExact(sp, ray, planeFn(s), list[0].t);
    }
}
