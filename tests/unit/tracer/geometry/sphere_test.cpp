// Sphere crossings, surface points and their error bounds.
#include "geometry_test_support.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

SurfaceFn sphereFn(const scene::SphereShape& s) {
    return [s](const LVec& p) { return length(p - LVec(s.center)) - LD(s.radius); };
}

} // namespace

TEST_CASE("sphere: a line from outside enters and leaves") {
    SphereGeometry g({{0, 0, 0}, 1});
    CrossingList list;
    g.crossLine({{0, 0, -5}, {0, 0, 1}}, list);
    REQUIRE(list.count == 2);
    CHECK_FALSE(list.startsInside);
    CHECK(list[0].t == 4);
    CHECK(list[1].t == 6);
    SurfacePoint sp = g.surfaceAt({{0, 0, -5}, {0, 0, 1}}, list[0]);
    CHECK(sp.point == Vec3(0, 0, -1));
    CHECK(sp.normal == Vec3(0, 0, -1));
    CHECK(sp.shadingNormal == sp.normal);
    CHECK(sp.uv.x == Approx(0.75));
    CHECK(sp.uv.y == Approx(0.5));
}

TEST_CASE("sphere: from inside the line still reports the crossing behind") {
    SphereGeometry g({{1, 2, 3}, 2});
    CrossingList list;
    Ray ray{{1, 2, 3}, {1, 0, 0}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == -2);
    CHECK(list[1].t == 2);
    Crossing c{};
    REQUIRE(firstCrossingIn(Geometry(g), ray, 0, kInfinity, c));
    CHECK(c.t == 2);
    SurfacePoint sp = g.surfaceAt(ray, c);
    CHECK(sp.normal == Vec3(1, 0, 0)); // outward even when hit from inside
    CHECK(sp.uv.y == Approx(0.5));
}

TEST_CASE("sphere: origin past the sphere gives only negative crossings") {
    SphereGeometry g({{0, 0, 0}, 1});
    CrossingList list;
    g.crossLine({{0, 0, 5}, {0, 0, 1}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == -6);
    CHECK(list[1].t == -4);
    Crossing c{};
    CHECK_FALSE(firstCrossingIn(Geometry(g), Ray{{0, 0, 5}, {0, 0, 1}}, 0, kInfinity, c));
}

TEST_CASE("sphere: a non-unit direction keeps t in ray units") {
    SphereGeometry g({{0, 0, 0}, 1});
    CrossingList list;
    g.crossLine({{0, 0, -5}, {0, 0, 2}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == 2);
    CHECK(list[1].t == 3);
}

TEST_CASE("sphere: tangent and grazing lines give zero or two crossings") {
    SphereGeometry g({{0, 0, 0}, 1});
    CrossingList list;
    g.crossLine({{1, 0, -5}, {0, 0, 1}}, list);
    CHECK((list.count == 0 || list.count == 2));
    if (list.count == 2) CHECK(list[0].t == Approx(list[1].t).margin(1e-6));
    g.crossLine({{1 + 1e-12, 0, -5}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
    g.crossLine({{1 - 1e-12, 0, -5}, {0, 0, 1}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t < list[1].t);
    // Lines at all angles skimming the surface: never an odd count.
    Random rng(7);
    for (int i = 0; i < 2000; ++i) {
        Vec3 n = rng.unit();
        Vec3 tangent = glm::normalize(glm::cross(n, rng.unit()));
        Ray ray{n * (1 + rng.uniform(-1e-9, 1e-9)) - 3.0 * tangent,
                tangent * rng.uniform(0.1, 10.0)};
        g.crossLine(ray, list);
        CHECK(list.count % 2 == 0);
        checkSorted(list);
    }
}

TEST_CASE("sphere: zero radius draws nothing") {
    SphereGeometry g({{0, 0, 0}, 0});
    CrossingList list;
    g.crossLine({{0, 0, -5}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
    g.crossLine({{0, 0, 0}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
    CHECK(g.bounds().empty());
    CHECK(g.solid());
}

TEST_CASE("sphere: random lines have bounded, outward, on-surface hits") {
    Random rng(1);
    for (int i = 0; i < 3000; ++i) {
        scene::SphereShape s{rng.inBox(5), rng.uniform(0.01, 3)};
        SphereGeometry g(s);
        Ray ray = rng.lineThrough(s.center + 0.99 * s.radius * rng.unit(), rng.uniform(0.5, 20));
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 2);
        checkAlternates(
            list, ray, [&](const LVec& p) { return sphereFn(s)(p) < 0; }, true);
        for (int k = 0; k < list.count; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            CHECK(glm::dot(sp.normal, sp.point - s.center) > 0);
            CHECK(glm::dot(sp.normal, ray.dir) * (k == 0 ? -1 : 1) >=
                  0); // enter against n, leave along
            CHECK(g.bounds().contains(sp.point));
            CHECK((sp.uv.x >= 0 && sp.uv.x < 1 && sp.uv.y >= 0 && sp.uv.y <= 1));
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            checkBoundContainsExact(sp, ray, sphereFn(s), list[k].t);
        }
    }
}

TEST_CASE("sphere: a far origin keeps the crossings accurate") {
    scene::SphereShape s{{3, -2, 1}, 0.5};
    SphereGeometry g(s);
    Random rng(3);
    for (int i = 0; i < 200; ++i) {
        Ray ray = rng.lineThrough(s.center + 0.4 * rng.unit(), 1e6);
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 2);
        for (int k = 0; k < 2; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkBoundContainsExact(sp, ray, sphereFn(s), list[k].t);
            CHECK(std::abs(glm::length(sp.point - s.center) - 0.5) < 1e-15 * 8);
        }
    }
}

// A nearly tangent line's t is off by about 1/|n·d| times the distance that error stands for,
// almost along the surface. The bound covers the distance from the surface only, so a spawned
// ray's offset stays a few roundings of the point, not the error in t.
TEST_CASE("sphere: a grazing hit's bound is its distance from the surface") {
    scene::SphereShape s{{0.3, -0.2, 0.7}, 1};
    SphereGeometry g(s);
    const Vec3 m = glm::normalize(Vec3(-0.2, 1, 0.1));
    const Vec3 along = glm::normalize(glm::cross(m, Vec3(1, 0.3, 0.2)));
    for (double cosine : {1e-3, 1e-5, 1e-7}) {
        // A line through the tangent point c + r·m, turned by `cosine` into the sphere.
        Vec3 touch = s.center + s.radius * m;
        Vec3 dir = glm::normalize(along - cosine * m);
        Ray ray{touch - 4.0 * dir, dir};
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 2);
        SurfacePoint sp = g.surfaceAt(ray, list[0]);
        INFO("n·d " << glm::dot(sp.normal, dir));
        double offset = glm::dot(absolute(sp.normal), sp.pointError);
        CHECK(offset < errorGamma(64) * (sumAbs(sp.point) + s.radius));
        checkBoundContainsExact(sp, ray, sphereFn(s), list[0].t);
    }
}
