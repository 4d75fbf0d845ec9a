// Superellipsoid crossings and surface points against a long-double reference: convex and
// star-shaped exponents, tangent, far and degenerate lines.
#include "geometry_test_support.hpp"

#include <algorithm>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// The implicit function written as POV-Ray documents it, in long double.
struct ExactSuperellipsoid {
    LD e, n;

    LD implicit(const LVec& p) const {
        LD section = std::pow(std::fabs(p.x), 2 / e) + std::pow(std::fabs(p.y), 2 / e);
        return std::pow(section, e / n) + std::pow(std::fabs(p.z), 2 / n) - 1;
    }
    /// The implicit function over the length of its gradient: a signed distance near the
    /// surface (to first order), as the bound checks want.
    LD distance(const LVec& p) const {
        const LD ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
        const LD section = std::pow(ax, 2 / e) + std::pow(ay, 2 / e);
        // ∂/∂x of section^(e/n) is (e/n)·section^(e/n − 1)·(2/e)·|x|^(2/e − 1), and so on.
        const LD outer = section > 0 ? (2 / n) * std::pow(section, e / n - 1) : 0;
        LVec g(outer * (ax > 0 ? std::pow(ax, 2 / e - 1) : 0),
               outer * (ay > 0 ? std::pow(ay, 2 / e - 1) : 0),
               (2 / n) * (az > 0 ? std::pow(az, 2 / n - 1) : 0));
        const LD len = length(g);
        return len > 0 ? implicit(p) / len : implicit(p);
    }
    /// Every crossing of the line inside the cube, by dense sampling and bisection.
    std::vector<LD> roots(const Ray& ray) const {
        LVec o(ray.origin), d(ray.dir);
        LD dd = dot(d, d);
        LD tc = -dot(o, d) / dd;
        LD half = 1.8L / std::sqrt(dd);
        std::vector<LD> out;
        const int steps = 4000;
        auto g = [&](LD t) { return implicit(o + t * d); };
        // Sampled in double (only the signs matter there), each change bisected in long double.
        auto coarse = [&](LD t) {
            const LVec p = o + t * d;
            return std::pow(std::pow(std::fabs(double(p.x)), 2 / double(e)) +
                                std::pow(std::fabs(double(p.y)), 2 / double(e)),
                            double(e / n)) +
                   std::pow(std::fabs(double(p.z)), 2 / double(n)) - 1;
        };
        LD prevT = tc - half;
        double prevG = coarse(prevT);
        for (int i = 1; i <= steps; ++i) {
            LD t = tc - half + 2 * half * i / steps;
            double gt = coarse(t);
            if ((gt < 0) != (prevG < 0)) out.push_back(bisectSignChange(g, prevT, t, g(prevT)));
            prevT = t;
            prevG = gt;
        }
        return out;
    }
};

/// Random lines through the cube of one shape: crossings alternate with the exact inside,
/// match the reference roots, and their surface points are bounded as the renderer needs.
int checkRandomLines(double e, double n, uint64_t seed, int lines) {
    Random rng(seed);
    ExactSuperellipsoid exact{e, n};
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{e, n});
    int most = 0;
    for (int i = 0; i < lines; ++i) {
        Ray ray = rng.lineThrough(rng.inBox(1.1), rng.uniform(0.5, 20));
        CrossingList list;
        g.crossLine(ray, list);
        INFO("e " << e << " n " << n << " case " << i);
        checkAlternates(
            list, ray, [&](const LVec& p) { return exact.implicit(p) < 0; }, true);
        most = std::max(most, list.count);
        std::vector<LD> roots = exact.roots(ray);
        if (roots.size() == size_t(list.count)) {
            for (int k = 0; k < list.count; ++k)
                CHECK(std::fabs(list[k].t - roots[size_t(k)]) * glm::length(ray.dir) < 1e-10);
        } else {
            // Only a line grazing the surface may disagree with the sampled reference.
            CHECK(std::abs(int(roots.size()) - list.count) == 2);
        }
        for (int k = 0; k < list.count; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            CHECK(g.bounds().contains(sp.point));
            CHECK((sp.uv.x >= 0 && sp.uv.x < 1 && sp.uv.y >= 0 && sp.uv.y <= 1));
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            CHECK(glm::dot(sp.normal, ray.dir) * (k % 2 == 0 ? -1 : 1) > 0);
            checkBoundContainsExact(
                sp, ray, [&](const LVec& p) { return exact.distance(p); }, list[k].t);
        }
    }
    return most;
}

} // namespace

TEST_CASE("superellipsoid: e = n = 1 is the unit sphere") {
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{1, 1});
    CHECK(g.solid());
    CHECK(g.convex());
    CrossingList list;
    Ray ray{{-5, 0.6, 0}, {2, 0, 0}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2.1).epsilon(1e-14));
    CHECK(list[1].t == Approx(2.9).epsilon(1e-14));
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.normal.x == Approx(-0.8));
    CHECK(sp.normal.y == Approx(0.6));
    CHECK(sp.point.x == Approx(-0.8));
}

TEST_CASE("superellipsoid: small exponents approach the cube, with flat faces") {
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{0.02, 0.02});
    CrossingList list;
    Ray ray{{0.3, 0.2, -4}, {0, 0, 1}};
    g.crossLine(ray, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3).epsilon(1e-9));
    CHECK(list[1].t == Approx(5).epsilon(1e-9));
    SurfacePoint sp = g.surfaceAt(ray, list[0]);
    CHECK(sp.normal.z == Approx(-1).margin(1e-9));
}

TEST_CASE("superellipsoid: a star (e, n above 2) is not convex; a line can cross its arms") {
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{3, 3});
    CHECK_FALSE(g.convex());
    CHECK_FALSE(isBoundedConvex(Geometry(g)));
    // Along the x arm, just off its axis: |x|^(2/3) = 1 − 2·0.05^(2/3), so |x| = 0.6219.
    CrossingList list;
    g.crossLine({{-3, 0.05, 0.05}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    const double reach = std::pow(1 - 2 * std::pow(0.05, 2.0 / 3), 1.5);
    CHECK(list[0].t == Approx(3 - reach).epsilon(1e-12));
    CHECK(list[1].t == Approx(3 + reach).epsilon(1e-12));
    // Across the y arm, far from the x arm: two crossings near x = 0.
    g.crossLine({{-3, 0.5, 0.02}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(std::abs(list[0].t - 3) < 0.2);
    CHECK(std::abs(list[1].t - 3) < 0.2);
}

TEST_CASE("superellipsoid: random lines, convex exponents") {
    for (auto [e, n] : {std::pair{1.0, 1.0}, {0.3, 0.6}, {2.0, 0.5}, {0.1, 1.7}, {1.0, 2.0}}) {
        CHECK(checkRandomLines(e, n, 51, 300) <= 2);
    }
}

TEST_CASE("superellipsoid: random lines, star-shaped exponents") {
    int most = 0;
    for (auto [e, n] : {std::pair{2.5, 2.5}, {3.0, 1.0}, {1.0, 3.5}, {4.0, 4.0}, {2.2, 0.3}})
        most = std::max(most, checkRandomLines(e, n, 52, 300));
    CHECK(most >= 4);                           // the arms are crossed
    CHECK(most <= 6);                           // as many as a star-shaped one can have
}

TEST_CASE("superellipsoid: lines from 1e5 away still find accurate roots") {
    Random rng(53);
    ExactSuperellipsoid exact{0.5, 0.8};
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{0.5, 0.8});
    for (int i = 0; i < 200; ++i) {
        Ray ray = rng.lineThrough(rng.inBox(0.9), 1e5);
        CrossingList list;
        g.crossLine(ray, list);
        std::vector<LD> roots = exact.roots(ray);
        INFO("case " << i);
        if (roots.size() != size_t(list.count)) {
            CHECK(std::abs(int(roots.size()) - list.count) == 2); // near-tangent only
            continue;
        }
        // t is about 1e5 / |d|: an error of a few of its ulps, more on a nearly tangent line.
        for (int k = 0; k < list.count; ++k)
            CHECK(std::fabs(list[k].t - roots[size_t(k)]) * glm::length(ray.dir) < 1e-9);
    }
}

TEST_CASE("superellipsoid: lines that miss the cube, or touch it only, cross nothing") {
    SuperellipsoidGeometry g(scene::SuperellipsoidShape{0.5, 0.5});
    CrossingList list;
    g.crossLine({{-5, 2, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
    g.crossLine({{-5, 0.999, 0.999}, {1, 0, 0}}, list); // inside the cube, outside the rounded edge
    CHECK(list.count == 0);
    g.crossLine({{0, 0, 0}, {0, 0, 0}}, list);
    CHECK(list.count == 0);
}

TEST_CASE("superellipsoid: exponents at zero or not finite draw nothing") {
    for (auto [e, n] : {std::pair{0.0, 1.0}, {1.0, -1.0}, {std::nan(""), 1.0}, {1.0, HUGE_VAL}}) {
        SuperellipsoidGeometry g(scene::SuperellipsoidShape{e, n});
        CrossingList list;
        g.crossLine({{-5, 0, 0}, {1, 0, 0}}, list);
        CHECK(list.count == 0);
        CHECK(g.bounds().empty());
    }
}
