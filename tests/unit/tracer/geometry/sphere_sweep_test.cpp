// Sphere-sweep crossings and surface points against a long-double reference: capsules with
// exact answers, a sphere swallowing its neighbour, and random lines through linear, cubic and
// B-spline sweeps, with and without self-overlap.
#include "geometry_test_support.hpp"

#include "tracer/geometry/sphere_sweep.hpp"

#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// The sweep in long double: min over the curve of |p − c(u)| − r(u), below 0 inside (the
/// distance from the surface outside; 1-Lipschitz everywhere), the minimum found by sampling u
/// densely and narrowing around the best samples.
struct ExactSweep {
    std::vector<scene::CurveSegmentOf<glm::dvec4>> segments;

    explicit ExactSweep(const scene::SphereSweepShape& s) {
        std::vector<glm::dvec4> spheres;
        for (size_t i = 0; i < s.points.size(); ++i) spheres.emplace_back(s.points[i], s.radii[i]);
        segments = scene::curveSegmentsOf(std::span<const glm::dvec4>(spheres), s.spline);
    }
    static LD gap(const scene::CurveSegmentOf<glm::dvec4>& s, const LVec& p, LD u) {
        LD c[4];
        for (int k = 0; k < 4; ++k)
            c[k] = ((LD(s.a[k]) * u + LD(s.b[k])) * u + LD(s.c[k])) * u + LD(s.d[k]);
        return length(p - LVec(c[0], c[1], c[2])) - std::fabs(c[3]);
    }
    LD operator()(const LVec& p) const {
        constexpr int kSamples = 256;
        LD best = INFINITY;
        for (const auto& s : segments) {
            // The least samples, each refined by golden sections within a sample either side.
            std::vector<std::pair<LD, int>> samples;
            for (int i = 0; i <= kSamples; ++i) samples.push_back({gap(s, p, LD(i) / kSamples), i});
            std::partial_sort(samples.begin(), samples.begin() + 3, samples.end());
            for (int k = 0; k < 3; ++k) {
                LD lo = std::max(LD(0), LD(samples[k].second - 1) / kSamples);
                LD hi = std::min(LD(1), LD(samples[k].second + 1) / kSamples);
                for (int i = 0; i < 80; ++i) {
                    const LD a = lo + (hi - lo) * 0.381966L, b = hi - (hi - lo) * 0.381966L;
                    if (gap(s, p, a) < gap(s, p, b))
                        hi = b;
                    else
                        lo = a;
                }
                best = std::min({best, gap(s, p, lo), samples[k].first});
            }
        }
        return best;
    }
};

scene::SphereSweepShape sweep(std::vector<glm::dvec3> points, std::vector<double> radii,
                              scene::SplineKind spline) {
    return {std::move(points), std::move(radii), spline};
}

/// Random lines through the sweep's box: crossings alternate with the exact inside test, and
/// each surface point's error bound holds the exact surface.
void checkRandomLines(const scene::SphereSweepShape& shape, uint64_t seed, int lines) {
    const SphereSweepGeometry g(shape);
    const ExactSweep exact(shape);
    const SurfaceFn f = [&](const LVec& p) { return exact(p); };
    Random random(seed);
    CrossingList list;
    int hits = 0;
    for (int i = 0; i < lines; ++i) {
        const Ray ray = random.lineThrough(random.pointIn(g.bounds()), 20);
        INFO("line " << i);
        g.crossLine(ray, list);
        checkAlternates(
            list, ray, [&](const LVec& p) { return exact(p) < 0; }, true);
        for (int k = 0; k < list.count; ++k) {
            const SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            checkBoundContainsExact(sp, ray, f, list[k].t);
            // Outward: the reference grows along the normal.
            CHECK(exact(LVec(sp.point + 1e-6 * sp.normal)) >
                  exact(LVec(sp.point - 1e-6 * sp.normal)));
        }
        hits += list.count > 0;
    }
    CHECK(hits > lines / 4);
}

} // namespace

TEST_CASE("A straight sweep of one radius is a capsule", "[sphere_sweep]") {
    const SphereSweepGeometry g(
        sweep({{0, 0, 0}, {2, 0, 0}}, {0.5, 0.5}, scene::SplineKind::Linear));
    CrossingList list;
    // Across the middle: the cylinder's sides.
    g.crossLine({{1, -3, 0}, {0, 1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2.5).epsilon(1e-14));
    CHECK(list[1].t == Approx(3.5).epsilon(1e-14));
    // Along the axis: the round ends.
    g.crossLine({{-3, 0, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2.5).epsilon(1e-14));
    CHECK(list[1].t == Approx(5.5).epsilon(1e-14));
    const SurfacePoint end = g.surfaceAt({{-3, 0, 0}, {1, 0, 0}}, list[0]);
    CHECK(end.normal.x == Approx(-1));
    // Through an end's round part, off the axis.
    g.crossLine({{2.3, -3, 0}, {0, 1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3 - 0.4).epsilon(1e-14));
    // Past the end: nothing.
    g.crossLine({{2.6, -3, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
}

TEST_CASE("A sweep whose radius grows faster than it moves is its largest sphere",
          "[sphere_sweep]") {
    const SphereSweepGeometry g(sweep({{0, 0, 0}, {1, 0, 0}}, {0.1, 2}, scene::SplineKind::Linear));
    CrossingList list;
    g.crossLine({{1, -5, 0}, {0, 1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3).epsilon(1e-14));
    CHECK(list[1].t == Approx(7).epsilon(1e-14));
    g.crossLine({{-5, 0, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(4).epsilon(1e-14));
}

TEST_CASE("A line through two arms of a bent sweep crosses it four times", "[sphere_sweep]") {
    // A U of three straight pieces; a line across both arms.
    const SphereSweepGeometry g(sweep({{0, 2, 0}, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}},
                                      {0.3, 0.3, 0.3, 0.3}, scene::SplineKind::Linear));
    CrossingList list;
    g.crossLine({{-1, 1, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 4);
    CHECK(list[0].t == Approx(0.7));
    CHECK(list[1].t == Approx(1.3));
    CHECK(list[2].t == Approx(2.7));
    CHECK(list[3].t == Approx(3.3));
}

TEST_CASE("Too few points give no sweep", "[sphere_sweep]") {
    const SphereSweepGeometry g(
        sweep({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {1, 1, 1}, scene::SplineKind::Cubic));
    CrossingList list;
    g.crossLine({{1, -5, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    CHECK(g.bounds().empty());
}

TEST_CASE("Random lines through linear, cubic and B-spline sweeps", "[sphere_sweep]") {
    const std::vector<glm::dvec3> zigzag = {
        {-2, 0, 0}, {-1, 1.5, 0.5}, {0, -0.5, 1}, {1, 1, -0.5}, {2, 0, 0}};
    const std::vector<double> radii = {0.3, 0.5, 0.2, 0.6, 0.3};
    SECTION("linear") {
        checkRandomLines(sweep(zigzag, radii, scene::SplineKind::Linear), 1, 30);
    }
    SECTION("cubic") {
        checkRandomLines(sweep(zigzag, radii, scene::SplineKind::Cubic), 2, 30);
    }
    SECTION("bspline") {
        checkRandomLines(sweep(zigzag, radii, scene::SplineKind::BSpline), 3, 30);
    }
    SECTION("a cubic loop that runs through itself") {
        const std::vector<glm::dvec3> loop = {{-1, -1, 0}, {1, 0, 0},    {0, 1, 0.3},
                                              {-1, 0, 0},  {1, -1, 0.2}, {1, 1, 0}};
        checkRandomLines(sweep(loop, {0.2, 0.3, 0.4, 0.3, 0.2, 0.1}, scene::SplineKind::Cubic), 4,
                         30);
    }
}
