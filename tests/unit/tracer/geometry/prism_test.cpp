// Prism crossings and surface points: against a box, an even-odd reference in long double
// for straight outlines and a finely flattened one for curves, conic sweeps, many walls, far
// lines and outlines that do not close.
#include "geometry_test_support.hpp"

#include "tracer/geometry/prism.hpp"

#include <algorithm>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

using V2 = glm::dvec2;

/// Whether (x, z) is inside the closed polygon loops by the even-odd rule, in long double.
bool evenOdd(const std::vector<std::vector<V2>>& loops, LD x, LD z) {
    bool inside = false;
    for (const std::vector<V2>& loop : loops) {
        for (size_t i = 0; i < loop.size(); ++i) {
            const V2 a = loop[i], b = loop[(i + 1) % loop.size()];
            if ((LD(a.y) > z) == (LD(b.y) > z)) continue;
            const LD cx = a.x + (z - a.y) * (LD(b.x) - a.x) / (LD(b.y) - a.y);
            if (x < cx) inside = !inside;
        }
    }
    return inside;
}

/// The loops of a desc as polygons: straight outlines as written, curves flattened finely.
std::vector<std::vector<V2>> flattened(const scene::PrismShape& desc, int perSegment) {
    std::vector<std::vector<V2>> out;
    for (const auto& loop : scene::curveLoops(desc.points, desc.spline).loops) {
        std::vector<V2>& poly = out.emplace_back();
        for (const scene::CurveSegment& s : loop)
            for (int k = 0; k < perSegment; ++k) poly.push_back(s.at(double(k) / perSegment));
    }
    return out;
}

/// The exact solid: between the heights, and inside the outline (scaled by y when conic).
std::function<bool(const LVec&)> insideOf(const scene::PrismShape& desc, int perSegment) {
    auto loops = flattened(desc, perSegment);
    return [=](const LVec& p) {
        if (p.y < LD(desc.from) || p.y > LD(desc.to)) return false;
        const LD s = desc.conic ? p.y : 1;
        return evenOdd(loops, p.x / s, p.z / s);
    };
}

scene::PrismShape star(int arms, double inner) {
    scene::PrismShape s;
    for (int i = 0; i < 2 * arms; ++i) {
        const double r = i % 2 == 0 ? 1 : inner, a = i * kPi / arms;
        s.points.push_back({r * std::cos(a), r * std::sin(a)});
    }
    s.points.push_back(s.points.front());
    return s;
}

/// Random lines through the solid's bounds: crossings sorted, even, alternating with the
/// reference's inside; returns the most crossings one line had.
int checkRandomLines(const scene::PrismShape& desc, int perSegment, uint64_t seed, int lines) {
    const PrismGeometry g(desc);
    const auto inside = insideOf(desc, perSegment);
    const Bounds3 b = g.bounds();
    Random rng(seed);
    int most = 0;
    for (int i = 0; i < lines; ++i) {
        const Vec3 target = rng.pointIn(b);
        const Ray ray = rng.lineThrough(target, 5);
        CrossingList list;
        g.crossLine(ray, list);
        checkAlternates(list, ray, inside, true);
        most = std::max(most, list.count);
    }
    return most;
}

} // namespace

TEST_CASE("prism: a square outline is a box") {
    scene::PrismShape s;
    s.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    s.from = -0.5;
    s.to = 2;
    const PrismGeometry g(s);
    CrossingList list;
    g.crossLine({{-5, 0.3, 0.2}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(4));
    CHECK(list[1].t == Approx(6));
    const SurfacePoint sp = g.surfaceAt({{-5, 0.3, 0.2}, {1, 0, 0}}, list[0]);
    CHECK(sp.normal.x == Approx(-1));
    CHECK(sp.point.x == Approx(-1));
    g.crossLine({{0.2, 9, 0.4}, {0, -1, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(7));
    CHECK(list[1].t == Approx(9.5));
    CHECK(g.surfaceAt({{0.2, 9, 0.4}, {0, -1, 0}}, list[0]).normal.y == Approx(1));
    CHECK(g.surfaceAt({{0.2, 9, 0.4}, {0, -1, 0}}, list[1]).normal.y == Approx(-1));
    CHECK(g.bounds().lo.y <= -0.5);
    CHECK(g.bounds().hi.x >= 1);
}

TEST_CASE("prism: a hole by the even-odd rule, its walls facing into it") {
    // Both loops counter-clockwise, both clockwise, and one each way: the normals face out of
    // the solid whichever way a loop runs.
    const std::vector<V2> outer = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    const std::vector<V2> hole = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5}};
    for (int variant = 0; variant < 4; ++variant) {
        std::vector<V2> a = outer, b = hole;
        if (variant & 1) std::reverse(a.begin(), a.end());
        if (variant & 2) std::reverse(b.begin(), b.end());
        scene::PrismShape s;
        s.points = a;
        s.points.insert(s.points.end(), b.begin(), b.end());
        const PrismGeometry g(s);
        CrossingList list;
        g.crossLine({{0.1, 5, 0.1}, {0, -1, 0}}, list);
        CHECK(list.count == 0); // down through the hole
        const Ray across{{-5, 0.5, 0.1}, {1, 0, 0}};
        g.crossLine(across, list);
        REQUIRE(list.count == 4);
        CHECK(list[1].t == Approx(4.5));
        CHECK(g.surfaceAt(across, list[0]).normal.x == Approx(-1));
        CHECK(g.surfaceAt(across, list[1]).normal.x == Approx(1)); // into the hole
        CHECK(g.surfaceAt(across, list[2]).normal.x == Approx(-1));
        CHECK(g.surfaceAt(across, list[3]).normal.x == Approx(1));
    }
}

TEST_CASE("prism: random lines, straight outlines") {
    CHECK(checkRandomLines(star(5, 0.4), 1, 61, 400) >= 4);
    scene::PrismShape conic = star(5, 0.4);
    conic.conic = true;
    conic.from = 0.3;
    conic.to = 1.7;
    CHECK(checkRandomLines(conic, 1, 62, 400) >= 4);
}

TEST_CASE("prism: random lines, curved outlines") {
    scene::PrismShape s = star(5, 0.5);
    s.points.pop_back();
    std::vector<V2> cubic = {s.points.back()};
    cubic.insert(cubic.end(), s.points.begin(), s.points.end());
    cubic.push_back(s.points[0]);
    cubic.push_back(s.points[1]);
    s.points = cubic;
    s.spline = scene::SplineKind::Cubic;
    CHECK(checkRandomLines(s, 2000, 63, 300) >= 4);
    s.spline = scene::SplineKind::Quadratic;
    s.points.pop_back();
    CHECK(checkRandomLines(s, 2000, 64, 300) >= 4);
    scene::PrismShape b;
    b.spline = scene::SplineKind::Bezier;
    b.points = {{0, -1}, {2, -1}, {-1, 0.5}, {0, 1}, {0, 1}, {-2, 1}, {1, -0.5}, {0, -1}};
    b.conic = true;
    b.from = 0.5;
    CHECK(checkRandomLines(b, 2000, 65, 300) >= 4);
}

TEST_CASE("prism: more walls than the crossing list keeps in place") {
    const scene::PrismShape s = star(40, 0.3);
    const PrismGeometry g(s);
    const Ray ray{{-5, 0.5, 0.5}, {1, 0, 0}};
    CrossingList list;
    g.crossLine(ray, list);
    CHECK(list.count > CrossingList::kInPlace);
    checkAlternates(list, ray, insideOf(s, 1), true);
    CHECK(checkRandomLines(s, 1, 66, 300) > CrossingList::kInPlace);
}

TEST_CASE("prism: surface points, normals and error bounds") {
    const scene::PrismShape s = star(5, 0.4);
    const PrismGeometry g(s);
    const auto inside = insideOf(s, 1);
    const std::vector<std::vector<V2>> loops = flattened(s, 1);
    Random rng(67);
    int checked = 0;
    for (double far : {5.0, 1e5}) {
        for (int i = 0; i < 300; ++i) {
            const Ray ray =
                rng.lineThrough(rng.inBox(0.8) * Vec3(1, 0.5, 1) + Vec3(0, 0.5, 0), far);
            CrossingList list;
            g.crossLine(ray, list);
            for (int k = 0; k < list.count; ++k) {
                const SurfacePoint sp = g.surfaceAt(ray, list[k]);
                checkUnit(sp.normal);
                // The surface the crossing is on, as a distance function: a cap's plane or a
                // wall's vertical plane through its edge.
                SurfaceFn f;
                if (list[k].part < 2) {
                    const LD h = list[k].part == 0 ? s.from : s.to;
                    const bool bottom = list[k].part == 0;
                    f = [=](const LVec& p) { return bottom ? h - p.y : p.y - h; };
                } else {
                    const V2 a = s.points[list[k].part - 2], b = s.points[list[k].part - 1];
                    const LVec n(LD(b.y) - a.y, 0, LD(a.x) - b.x);
                    const LD len = length(n);
                    f = [=](const LVec& p) { return dot(p - LVec(a.x, 0, a.y), n) / len; };
                    // Outward: the solid's inside lies behind the normal.
                    const LVec q(sp.point);
                    const LD step = 1e-7L * (1 + length(q));
                    if (std::fabs(q.y - 0.5L) < 0.45L) {
                        CHECK(inside(q - step * LVec(sp.normal)));
                        CHECK_FALSE(inside(q + step * LVec(sp.normal)));
                    }
                }
                checkBoundContainsExact(sp, ray, f, list[k].t);
                ++checked;
            }
        }
    }
    CHECK(checked > 500);
}

TEST_CASE("prism: outlines that do not close, and equal heights, give nothing") {
    scene::PrismShape s;
    s.spline = scene::SplineKind::Cubic;
    s.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}};
    CrossingList list;
    PrismGeometry(s).crossLine({{-5, 0.5, 0.5}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
    scene::PrismShape flat = star(4, 0.5);
    flat.to = flat.from;
    PrismGeometry(flat).crossLine({{0, 5, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
}
