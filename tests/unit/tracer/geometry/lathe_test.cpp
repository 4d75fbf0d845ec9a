// Lathe crossings and surface points against a long-double reference: the four spline
// kinds, level and nearly level lines, lines along the axis, far lines, open curves.
#include "geometry_test_support.hpp"

#include "tracer/geometry/lathe.hpp"

#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// The curve of POV-Ray's lathe points in long double, and the solid it bounds: points of
/// the x-y plane (distance from the axis, height) whose ray toward +x crosses the curve an
/// odd number of times.
struct ExactLathe {
    std::vector<scene::CurveSegment> segments;
    LD outward; ///< +1 when the region lies left of the curve's direction

    struct LPoint {
        LD x, y;
    };
    static LD cubic(const scene::CurveSegment& s, int axis, LD u) {
        return ((LD(s.a[axis]) * u + s.b[axis]) * u + s.c[axis]) * u + s.d[axis];
    }
    static LD cubicSlope(const scene::CurveSegment& s, int axis, LD u) {
        return (3 * LD(s.a[axis]) * u + 2 * LD(s.b[axis])) * u + s.c[axis];
    }
    /// Every u in [0, 1) where the segment's height passes y, by bisection between the turns.
    static std::vector<LD> heightCrossings(const scene::CurveSegment& s, LD y) {
        std::vector<LD> split = {0};
        const LD a = 3 * LD(s.a.y), b = 2 * LD(s.b.y), c = s.c.y;
        if (a != 0) {
            const LD disc = b * b - 4 * a * c;
            if (disc > 0) {
                LD r0 = (-b - std::sqrt(disc)) / (2 * a), r1 = (-b + std::sqrt(disc)) / (2 * a);
                if (r0 > r1) std::swap(r0, r1);
                for (LD r : {r0, r1})
                    if (r > 0 && r < 1) split.push_back(r);
            }
        } else if (b != 0 && -c / b > 0 && -c / b < 1) {
            split.push_back(-c / b);
        }
        split.push_back(1);
        std::vector<LD> out;
        auto g = [&](LD u) { return cubic(s, 1, u) - y; };
        for (size_t i = 0; i + 1 < split.size(); ++i) {
            const LD lo = g(split[i]), hi = g(split[i + 1]);
            if ((lo < 0) != (hi < 0))
                out.push_back(bisectSignChange(g, split[i], split[i + 1], lo));
        }
        return out;
    }
    bool inside(const LVec& q) const {
        const LD rho = std::sqrt(q.x * q.x + q.z * q.z);
        int crossings = 0;
        for (const scene::CurveSegment& s : segments)
            for (LD u : heightCrossings(s, q.y))
                if (std::fabs(cubic(s, 0, u)) > rho) ++crossings;
        return crossings % 2 == 1;
    }
    /// The signed distance in the x-y plane to segment i's curve, positive outside.
    LD distance(const LVec& q, size_t i) const {
        const scene::CurveSegment& s = segments[i];
        const LD rho = std::sqrt(q.x * q.x + q.z * q.z);
        auto d2 = [&](LD u) {
            const LD dx = cubic(s, 0, u) - rho, dy = cubic(s, 1, u) - q.y;
            return dx * dx + dy * dy;
        };
        LD best = 0;
        for (int k = 1; k <= 2000; ++k)
            if (d2(LD(k) / 2000) < d2(best)) best = LD(k) / 2000;
        LD lo = std::max(LD(0), best - 1.0L / 2000), hi = std::min(LD(1), best + 1.0L / 2000);
        for (int k = 0; k < 200; ++k) { // golden-section-like narrowing of the nearest point
            const LD m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (d2(m1) < d2(m2))
                hi = m2;
            else
                lo = m1;
        }
        const LD u = 0.5L * (lo + hi);
        const LD tx = cubicSlope(s, 0, u), ty = cubicSlope(s, 1, u);
        const LD side = (rho - cubic(s, 0, u)) * ty - (q.y - cubic(s, 1, u)) * tx;
        return std::copysign(std::sqrt(d2(u)), side * outward);
    }
};

using Points = std::vector<glm::dvec2>;
const Points kGoblet = {{0, 0}, {0.8, 0}, {0.8, 0.2}, {0.2, 0.4}, {0.2, 1}, {0.7, 1.3}, {0, 1.4}};
const Points kBottle = {{0.5, -0.2}, {0, 0}, {0.6, 0.2}, {0.5, 0.9}, {0.2, 1.3}, {0, 1.5}};
/// Closed on itself, running clockwise: its normals must still point out.
const Points kRing = {{0.6, 0.8}, {0.9, 0.5}, {0.6, 0.2}, {0.3, 0.5},
                      {0.6, 0.8}, {0.9, 0.5}, {0.6, 0.2}};
const Points kDome = {{0, 0},     {0.5, 0},   {0.9, 0.3}, {0.7, 0.6},
                      {0.7, 0.6}, {0.5, 0.9}, {0.3, 1},   {0, 1}};

struct Case {
    const char* name;
    Points points;
    scene::SplineKind kind;
    LD outward;
    int most; ///< the most crossings a line can have
};
const Case kCases[] = {{"goblet", kGoblet, scene::SplineKind::Linear, 1, 4},
                       {"bottle", kBottle, scene::SplineKind::Quadratic, 1, 2},
                       {"ring", kRing, scene::SplineKind::Cubic, -1, 4},
                       {"dome", kDome, scene::SplineKind::Bezier, 1, 2},
                       // The ring's points close a B-spline too, which keeps inside them.
                       {"pebble ring", kRing, scene::SplineKind::BSpline, -1, 4}};

ExactLathe exactOf(const Case& c) {
    return {scene::curveSegments(c.points, c.kind), c.outward};
}

} // namespace

TEST_CASE("lathe: a rectangle turned is a cylinder, whichever way the line runs") {
    const LatheGeometry g(scene::LatheShape{{{0, 0}, {1, 0}, {1, 2}, {0, 2}}, {}});
    CHECK(g.solid());
    CrossingList list;
    for (double slope : {0.0, 1e-12, -1e-9, 1e-6}) {
        INFO("slope " << slope);
        const Ray across{{-5, 1, 0}, {1, slope, 0}};
        g.crossLine(across, list);
        REQUIRE(list.count == 2);
        CHECK(list[0].t == Approx(4).epsilon(1e-12));
        CHECK(list[1].t == Approx(6).epsilon(1e-12));
        CHECK(g.surfaceAt(across, list[0]).normal.x == Approx(-1));
        CHECK(g.surfaceAt(across, list[1]).normal.x == Approx(1));
    }
    const Ray down{{0.3, 5, 0.2}, {0, -1, 0}};
    g.crossLine(down, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3));
    CHECK(list[1].t == Approx(5));
    CHECK(g.surfaceAt(down, list[0]).normal.y == Approx(1));
    CHECK(g.surfaceAt(down, list[1]).normal.y == Approx(-1));
    const Ray axis{{0, -3, 0}, {0, 1, 0}}; // along the axis, through both discs' centres
    g.crossLine(axis, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3));
    CHECK(list[1].t == Approx(5));
    CHECK(g.bounds().hi.y >= 2);
    CHECK(g.bounds().lo.x <= -1);
}

TEST_CASE("lathe: random lines against the exact solid, for every spline kind") {
    for (const Case& c : kCases) {
        INFO(c.name);
        const LatheGeometry g(scene::LatheShape{c.points, c.kind});
        REQUIRE(g.solid());
        const ExactLathe exact = exactOf(c);
        const Bounds3 b = g.bounds();
        Random rng(81);
        int most = 0;
        for (int i = 0; i < 400; ++i) {
            const Vec3 target = rng.pointIn(b);
            const Ray ray = rng.lineThrough(target, 5);
            CrossingList list;
            g.crossLine(ray, list);
            checkAlternates(
                list, ray, [&](const LVec& q) { return exact.inside(q); }, true);
            most = std::max(most, list.count);
        }
        CHECK(most >= c.most);
    }
}

// 32 s in Release, 200 s under the sanitizers (its long-double references unoptimised there).
TEST_CASE("lathe: surface points, outward normals and error bounds", "[release-only]") {
    int checked = 0;
    for (const Case& c : kCases) {
        INFO(c.name);
        const LatheGeometry g(scene::LatheShape{c.points, c.kind});
        const ExactLathe exact = exactOf(c);
        const Vec3 centre = 0.5 * (g.bounds().lo + g.bounds().hi);
        Random rng(82);
        for (double far : {5.0, 1e5}) {
            for (int i = 0; i < 150; ++i) {
                const Ray ray = rng.lineThrough(centre + rng.inBox(0.4), far);
                CrossingList list;
                g.crossLine(ray, list);
                for (int k = 0; k < list.count; ++k) {
                    const SurfacePoint sp = g.surfaceAt(ray, list[k]);
                    checkUnit(sp.normal);
                    const size_t seg = list[k].part;
                    const LVec q(sp.point);
                    const LD step = 1e-6L;
                    if (std::sqrt(q.x * q.x + q.z * q.z) > 0.01L) {
                        CHECK(exact.inside(q - step * LVec(sp.normal)));
                        CHECK_FALSE(exact.inside(q + step * LVec(sp.normal)));
                    }
                    checkBoundContainsExact(
                        sp, ray, [&](const LVec& p) { return exact.distance(p, seg); }, list[k].t);
                    ++checked;
                }
            }
        }
    }
    CHECK(checked > 1000);
}

TEST_CASE("lathe: a curve that does not close is a surface") {
    // A lampshade: one straight segment, off the axis at both ends.
    const LatheGeometry shade(scene::LatheShape{{{1, 0}, {0.5, 1}}, {}});
    CHECK_FALSE(shade.solid());
    CrossingList list;
    shade.crossLine({{-5, 0.5, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 2);
    // Bézier segments that do not meet.
    CHECK_FALSE(
        LatheGeometry(scene::LatheShape{
                          {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0.9, 1}, {0.5, 1}, {0.5, 1}, {0, 1}},
                          scene::SplineKind::Bezier})
            .solid());
    CHECK(scene::curveEnclosesSolid(scene::curveSegments(kDome, scene::SplineKind::Bezier)));
}
