// Torus crossings (the quartic), surface points and their error bounds, near and far.
#include "geometry_test_support.hpp"

#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

struct ExactTorus {
    LVec center, axis; // axis unit
    LD major, minor;

    explicit ExactTorus(const scene::TorusShape& s) : center(s.center), major(s.major), minor(s.minor) {
        LVec a(s.axis);
        axis = (1 / length(a)) * a;
    }
    LD distance(const LVec& p) const {
        LVec q = p - center;
        LD z = dot(q, axis), rho = length(cross(q, axis));
        return std::sqrt((rho - major) * (rho - major) + z * z) - minor;
    }
    /// All crossings of the line, found by dense sampling and bisection in long double.
    std::vector<LD> roots(const Ray& ray) const {
        LVec o(ray.origin), d(ray.dir);
        LD dd = dot(d, d);
        LD tc = -dot(o - center, d) / dd;
        LD half = (major + minor) * 1.01L / std::sqrt(dd);
        std::vector<LD> out;
        const int n = 5000;
        auto g = [&](LD t) { return distance(o + t * d); };
        LD prevT = tc - half, prevG = g(prevT);
        for (int i = 1; i <= n; ++i) {
            LD t = tc - half + 2 * half * i / n, gt = g(t);
            if ((gt < 0) != (prevG < 0)) {
                out.push_back(bisectSignChange(g, prevT, t, prevG));
            }
            prevT = t;
            prevG = gt;
        }
        return out;
    }
};

} // namespace

TEST_CASE("torus: a line through the middle crosses four times") {
    TorusGeometry g({{0, 0, 0}, 1, 0.25, {0, 1, 0}});
    CHECK(g.solid());
    CrossingList list;
    Ray ray{{-5, 0, 0}, {1, 0, 0}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 4);
    CHECK_FALSE(list.startsInside);
    CHECK(list[0].t == Approx(3.75).epsilon(1e-15));
    CHECK(list[1].t == Approx(4.25).epsilon(1e-15));
    CHECK(list[2].t == Approx(5.75).epsilon(1e-15));
    CHECK(list[3].t == Approx(6.25).epsilon(1e-15));
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.normal.x == Approx(-1));
    CHECK(sp.point.x == Approx(-1.25));
    sp = g.surfaceAt(ray, list[1]);
    CHECK(sp.normal.x == Approx(1)); // the inner side of the tube faces the hole
    CHECK(sp.uv.y == Approx(0.5));   // the inner equator is half way round the tube
}

TEST_CASE("torus: through the hole, across the tube, from inside, behind, non-unit") {
    TorusGeometry g({{0, 0, 0}, 1, 0.25, {0, 1, 0}});
    CrossingList list;
    g.crossLine({{0, -5, 0}, {0, 1, 0}}, list); // along the axis
    CHECK(list.count == 0);
    g.crossLine({{1, -5, 0}, {0, 2, 0}}, list); // across the tube, non-unit direction
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2.375));
    CHECK(list[1].t == Approx(2.625));
    g.crossLine({{1, 0, 0}, {1, 0, 0}}, list); // from inside the tube
    REQUIRE(list.count == 4);
    CHECK(list[2].t == Approx(-0.25));
    CHECK(list[3].t == Approx(0.25));
    g.crossLine({{1, 0, 0}, {0, 0, 1}}, list); // inside the tube along its whole width
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(-0.75));
    CHECK(list[1].t == Approx(0.75));
    g.crossLine({{9, 0, 0}, {1, 0, 0}}, list); // past the torus
    REQUIRE(list.count == 4);
    CHECK(list[3].t < 0);
    g.crossLine({{-5, 0.3, 0}, {1, 0, 0}}, list); // above it
    CHECK(list.count == 0);
}

TEST_CASE("torus: tangent lines give an even number of crossings") {
    TorusGeometry g({{0, 0, 0}, 1, 0.25, {0, 1, 0}});
    CrossingList list;
    g.crossLine({{-5, 0.25, 0}, {1, 0, 0}}, list); // tangent to the top circle
    CHECK(list.count % 2 == 0);
    g.crossLine({{-5, 0, 1.25}, {1, 0, 0}}, list); // tangent to the outer equator
    CHECK(list.count % 2 == 0);
    g.crossLine({{-5, 0, 0.75}, {1, 0, 0}}, list); // tangent to the inner equator: touches twice
    CHECK(list.count % 2 == 0);
    Random rng(31);
    for (int i = 0; i < 2000; ++i) {
        double y = 0.25 * (1 + rng.uniform(-1e-9, 1e-9));
        Vec3 dir(std::cos(rng.uniform(0, 2 * kPi)), 0, std::sin(rng.uniform(0, 2 * kPi)));
        g.crossLine(
            {Vec3(0, y, 0) + rng.uniform(-0.5, 0.5) * Vec3(-dir.z, 0, dir.x) - 3.0 * dir, dir},
            list);
        CHECK(list.count % 2 == 0);
        checkSorted(list);
    }
}

TEST_CASE("torus: random lines around arbitrary axes") {
    Random rng(32);
    int fours = 0;
    for (int i = 0; i < 3000; ++i) {
        scene::TorusShape s{rng.inBox(5), rng.uniform(0.2, 3), 0, rng.unit() * rng.uniform(0.5, 2)};
        s.minor = s.major * rng.uniform(0.02, 0.9);
        ExactTorus exact(s);
        TorusGeometry g(s);
        Vec3 target = s.center + rng.inBox(s.major + s.minor);
        Ray ray = rng.lineThrough(target, rng.uniform(0.1, 30));
        CrossingList list;
        g.crossLine(ray, list);
        INFO("case " << i);
        checkAlternates(
            list, ray, [&](const LVec& p) { return exact.distance(p) < 0; }, true);
        fours += list.count == 4;
        std::vector<LD> roots = exact.roots(ray);
        if (roots.size() == size_t(list.count)) {
            for (int k = 0; k < list.count; ++k)
                CHECK(std::fabs(list[k].t - roots[size_t(k)]) * glm::length(ray.dir) <
                      1e-12 * (s.major + 1));
        } else {
            // Only near-tangent lines may disagree with the sampled reference.
            CHECK(std::abs(int(roots.size()) - list.count) == 2);
        }
        for (int k = 0; k < list.count; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            CHECK(g.bounds().contains(sp.point));
            CHECK((sp.uv.x >= 0 && sp.uv.x < 1 && sp.uv.y >= 0 && sp.uv.y < 1));
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            CHECK(glm::dot(sp.normal, ray.dir) * (k % 2 == 0 ? -1 : 1) > 0);
            checkBoundContainsExact(
                sp, ray, [&](const LVec& p) { return exact.distance(p); }, list[k].t);
        }
    }
    CHECK(fours > 50);
}

TEST_CASE("torus: lines from 1e5 away still find accurate roots") {
    Random rng(33);
    for (int i = 0; i < 300; ++i) {
        scene::TorusShape s{rng.inBox(2), 1, rng.uniform(0.1, 0.5), rng.unit()};
        ExactTorus exact(s);
        TorusGeometry g(s);
        Ray ray = rng.lineThrough(s.center + rng.inBox(1.2), 1e5);
        CrossingList list;
        g.crossLine(ray, list);
        std::vector<LD> roots = exact.roots(ray);
        INFO("case " << i);
        if (roots.size() != size_t(list.count)) {
            CHECK(std::abs(int(roots.size()) - list.count) == 2); // near-tangent only
            continue;
        }
        for (int k = 0; k < list.count; ++k) {
            // t is about 1e5 / |d|: an error of a few of its ulps only.
            CHECK(std::fabs(list[k].t - roots[size_t(k)]) * glm::length(ray.dir) < 2e-10);
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            checkBoundContainsExact(
                sp, ray, [&](const LVec& p) { return exact.distance(p); }, list[k].t);
        }
    }
}

TEST_CASE("torus: a spindle torus (minor > major) is still a closed solid") {
    scene::TorusShape s{{0, 0, 0}, 0.5, 1, {0, 0, 1}};
    ExactTorus exact(s);
    TorusGeometry g(s);
    CrossingList list;
    g.crossLine({{0, 0, -5}, {0, 0, 1}}, list); // along the axis: only the outer surface
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(5 - std::sqrt(0.75)));
    Random rng(34);
    for (int i = 0; i < 1000; ++i) {
        Ray ray = rng.lineThrough(rng.inBox(1.5), rng.uniform(2, 10));
        g.crossLine(ray, list);
        checkAlternates(
            list, ray, [&](const LVec& p) { return exact.distance(p) < 0; }, true);
    }
}

TEST_CASE("torus: zero radii draw nothing") {
    CrossingList list;
    TorusGeometry noMinor({{0, 0, 0}, 1, 0, {0, 1, 0}});
    noMinor.crossLine({{-5, 0, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
    TorusGeometry noMajor({{0, 0, 0}, 0, 1, {0, 1, 0}});
    noMajor.crossLine({{-5, 0, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
    CHECK(noMajor.bounds().empty());
}
