// Surface-of-revolution crossings and surface points against a long-double reference:
// random lines, level lines, end faces, a radius reaching the axis, far lines.
#include "geometry_test_support.hpp"

#include "tracer/geometry/sor.hpp"

#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// R(y), the radius squared, as POV-Ray defines it: the cubic in y through the squared
/// radii of the segment's two points with slopes 2x·dx/dy from their neighbours, in long
/// double; and the solid x² + z² ≤ R(y) between the second and the last but one point.
struct ExactSor {
    std::vector<glm::dvec2> p;

    bool segmentOf(LD y, size_t& i) const {
        for (i = 0; i + 3 < p.size(); ++i)
            if (y >= LD(p[i + 1].y) && y <= LD(p[i + 2].y)) return true;
        return false;
    }
    LD radiusSquared(LD y, size_t i) const {
        const LD y0 = p[i + 1].y, y1 = p[i + 2].y, h = y1 - y0, s = (y - y0) / h;
        const LD k0 = LD(p[i + 1].x) * p[i + 1].x, k1 = LD(p[i + 2].x) * p[i + 2].x;
        const LD m0 =
            h * 2 * LD(p[i + 1].x) * (LD(p[i + 2].x) - p[i].x) / (LD(p[i + 2].y) - p[i].y);
        const LD m1 =
            h * 2 * LD(p[i + 2].x) * (LD(p[i + 3].x) - p[i + 1].x) / (LD(p[i + 3].y) - p[i + 1].y);
        return (2 * s * s * s - 3 * s * s + 1) * k0 + (s * s * s - 2 * s * s + s) * m0 +
               (-2 * s * s * s + 3 * s * s) * k1 + (s * s * s - s * s) * m1;
    }
    bool inside(const LVec& q) const {
        size_t i;
        return segmentOf(q.y, i) && q.x * q.x + q.z * q.z <= radiusSquared(q.y, i);
    }
    /// (x² + z² − R) over its gradient's length: a distance near the side.
    LD sideDistance(const LVec& q, size_t i) const {
        const LD h = 1e-9L;
        const LD f = q.x * q.x + q.z * q.z - radiusSquared(q.y, i);
        const LD dR = (radiusSquared(q.y + h, i) - radiusSquared(q.y - h, i)) / (2 * h);
        const LD len = std::sqrt(4 * (q.x * q.x + q.z * q.z) + dR * dR);
        return len > 0 ? f / len : f;
    }
};

const std::vector<glm::dvec2> kVase = {{0.3, -0.2}, {0.5, 0},   {0.8, 0.4}, {0.4, 1},
                                       {0.35, 1.3}, {0.6, 1.6}, {0.7, 1.8}};
/// Its radius reaches the axis at both ends: cone-like tips.
const std::vector<glm::dvec2> kSpindle = {{0.2, -0.5}, {0, 0}, {0.6, 0.6}, {0, 1.4}, {0.3, 1.8}};

int checkRandomLines(const std::vector<glm::dvec2>& points, uint64_t seed, int lines) {
    const SorGeometry g(scene::SorShape{points, false});
    const ExactSor exact{points};
    const Bounds3 b = g.bounds();
    Random rng(seed);
    int most = 0;
    for (int i = 0; i < lines; ++i) {
        const Vec3 target = rng.pointIn(b);
        const Ray ray = rng.lineThrough(target, 5);
        CrossingList list;
        g.crossLine(ray, list);
        checkAlternates(
            list, ray, [&](const LVec& q) { return exact.inside(q); }, true);
        most = std::max(most, list.count);
    }
    return most;
}

} // namespace

TEST_CASE("sor: a constant radius is a cylinder with its end faces") {
    const SorGeometry g(scene::SorShape{{{1, -1}, {1, 0}, {1, 2}, {1, 3}}, false});
    CrossingList list;
    const Ray across{{-5, 1, 0}, {1, 0, 0}}; // level: the side at its own height
    g.crossLine(across, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(4));
    CHECK(list[1].t == Approx(6));
    CHECK(g.surfaceAt(across, list[0]).normal.x == Approx(-1));
    const Ray down{{0.3, 5, 0.2}, {0, -1, 0}};
    g.crossLine(down, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3));
    CHECK(list[1].t == Approx(5));
    CHECK(g.surfaceAt(down, list[0]).normal.y == Approx(1));
    CHECK(g.surfaceAt(down, list[1]).normal.y == Approx(-1));
    const Ray slanted{{-4.5, -4, 0.1}, {1, 1, 0}};
    g.crossLine(slanted, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].part == 0); // in through the bottom face
    CHECK(list[1].part >= 2); // out through the side
    CHECK(g.bounds().hi.y >= 2);
    CHECK(g.bounds().lo.x <= -1);
    // Open: the side only.
    SorGeometry(scene::SorShape{{{1, -1}, {1, 0}, {1, 2}, {1, 3}}, true}).crossLine(down, list);
    CHECK(list.count == 0);
}

TEST_CASE("sor: random lines against the exact solid") {
    CHECK(checkRandomLines(kVase, 71, 500) >= 4);
    CHECK(checkRandomLines(kSpindle, 72, 500) >= 2);
}

TEST_CASE("sor: surface points, outward normals and error bounds") {
    const SorGeometry g(scene::SorShape{kVase, false});
    const ExactSor exact{kVase};
    Random rng(73);
    int checked = 0;
    for (double far : {5.0, 1e5}) {
        for (int i = 0; i < 300; ++i) {
            const Ray ray = rng.lineThrough(Vec3(0, 0.8, 0) + rng.inBox(0.5), far);
            CrossingList list;
            g.crossLine(ray, list);
            for (int k = 0; k < list.count; ++k) {
                const SurfacePoint sp = g.surfaceAt(ray, list[k]);
                checkUnit(sp.normal);
                SurfaceFn f;
                if (list[k].part < 2) {
                    const LD h = list[k].part == 0 ? kVase[1].y : kVase[5].y;
                    const bool bottom = list[k].part == 0;
                    f = [=](const LVec& q) { return bottom ? h - q.y : q.y - h; };
                } else {
                    const size_t seg = list[k].part - 2;
                    f = [=](const LVec& q) { return exact.sideDistance(q, seg); };
                    const LVec q(sp.point);
                    const LD step = 1e-6L;
                    if (q.y > 0.01L && q.y < 1.59L) {
                        CHECK(exact.inside(q - step * LVec(sp.normal)));
                        CHECK_FALSE(exact.inside(q + step * LVec(sp.normal)));
                    }
                }
                checkBoundContainsExact(sp, ray, f, list[k].t);
                ++checked;
            }
        }
    }
    CHECK(checked > 500);
}

TEST_CASE("sor: heights that do not rise give nothing") {
    CrossingList list;
    SorGeometry(scene::SorShape{{{1, 0}, {1, 1}, {1, 1}, {1, 2}}, false})
        .crossLine({{0, 5, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
    SorGeometry(scene::SorShape{{{1, 0}, {1, 1}, {1, 2}}, false})
        .crossLine({{0, 5, 0}, {0, -1, 0}}, list);
    CHECK(list.count == 0);
}
