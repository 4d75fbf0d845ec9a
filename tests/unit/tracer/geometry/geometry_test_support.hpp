// Helpers for the primitive tests: long-double references, random lines and common checks.
#pragma once

#include "tracer/geometry/geometry.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>

namespace crt::tracer::test {

using LD = long double;

/// A vector in long double (64-bit mantissa on x86), for references 11 bits finer than double.
struct LVec {
    LD x = 0, y = 0, z = 0;
    LVec() = default;
    LVec(LD x_, LD y_, LD z_) : x(x_), y(y_), z(z_) {}
    explicit LVec(const Vec3& v) : x(v.x), y(v.y), z(v.z) {}
    LD operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};
inline LVec operator+(LVec a, LVec b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline LVec operator-(LVec a, LVec b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline LVec operator*(LD s, LVec a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline LD dot(LVec a, LVec b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline LVec cross(LVec a, LVec b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline LD length(LVec a) {
    return std::sqrt(dot(a, a));
}

/// The parameter where g changes sign in [lo, hi] (g(lo) = glo, g(hi) of the other sign),
/// by bisection in long double down to adjacent representable values.
template <typename G> LD bisectSignChange(const G& g, LD lo, LD hi, LD glo) {
    for (int i = 0; i < 200; ++i) {
        LD mid = 0.5L * (lo + hi);
        if (mid == lo || mid == hi) break;
        LD gm = g(mid);
        if ((gm < 0) == (glo < 0)) {
            lo = mid;
            glo = gm;
        } else {
            hi = mid;
        }
    }
    return 0.5L * (lo + hi);
}

/// A signed function of a point that vanishes exactly on one surface (in long double).
using SurfaceFn = std::function<LD(const LVec&)>;

/// The exact point where the ray's line meets the surface f near parameter t: brackets a sign
/// change around t and bisects in long double.
inline bool exactHit(const Ray& ray, const SurfaceFn& f, double t, LVec& hit) {
    LVec o(ray.origin), d(ray.dir);
    auto g = [&](LD s) { return f(o + s * d); };
    LD h = 1e-12L * (1 + std::fabs(LD(t)));
    LD lo = t - h, hi = t + h;
    LD glo = g(lo), ghi = g(hi);
    for (int i = 0; i < 60 && (glo < 0) == (ghi < 0); ++i) {
        h *= 2;
        lo = t - h;
        hi = t + h;
        glo = g(lo);
        ghi = g(hi);
    }
    if ((glo < 0) == (ghi < 0)) return false;
    hit = o + bisectSignChange(g, lo, hi, glo) * d;
    return true;
}

/// The error bound of `sp` is pbrt's: the box around the point holds a point of the exact
/// surface (the one along the normal), and the point is off the surface by less than the box
/// projected onto the normal, which is what a spawned ray's offset rests on (f must be a
/// distance function: 1-Lipschitz). The box need not hold the exact crossing of the line: that
/// is off along the surface by the error in t. The point is still near it.
inline void checkBoundContainsExact(const SurfacePoint& sp, const Ray& ray, const SurfaceFn& f,
                                    double t) {
    LVec exact, onSurface;
    REQUIRE(exactHit(ray, f, t, exact));
    REQUIRE(exactHit(Ray{sp.point, sp.normal}, f, 0, onSurface));
    for (int i = 0; i < 3; ++i) {
        INFO("component " << i << ": point " << sp.point[i] << " nearest "
                          << double(onSurface[i]) << " crossing " << double(exact[i])
                          << " bound " << sp.pointError[i]);
        REQUIRE(std::isfinite(sp.pointError[i]));
        REQUIRE(sp.pointError[i] >= 0);
        // The reference is in long double: exact to a few long-double roundings.
        LD slack = 1e-18L * (1 + std::fabs(LD(sp.point[i])));
        CHECK(std::fabs(LD(sp.point[i]) - onSurface[i]) <= LD(sp.pointError[i]) + slack);
        // A nearly tangent line's crossing is ill-conditioned: the error in t is about the
        // square root of a rounding.
        CHECK(std::fabs(LD(sp.point[i]) - exact[i]) <= 1e-6L * (1 + length(exact)));
    }
    LD off = std::fabs(f(LVec(sp.point)));
    CHECK(off <= LD(glm::dot(absolute(sp.normal), sp.pointError)));
}

inline void checkUnit(const Vec3& n) {
    CHECK(std::abs(glm::length(n) - 1) < 1e-12);
}

inline void checkSorted(const CrossingList& list) {
    for (int i = 1; i < list.count; ++i) CHECK(list[i - 1].t <= list[i].t);
}

/// Crossings of a solid alternate with its inside, checked against an exact inside test at
/// the midpoints (skipping spans too short to judge), and a bounded solid has an even count.
inline void checkAlternates(const CrossingList& list, const Ray& ray,
                            const std::function<bool(const LVec&)>& inside, bool bounded) {
    checkSorted(list);
    if (bounded) {
        CHECK(list.count % 2 == 0);
        CHECK_FALSE(list.startsInside);
    }
    LVec o(ray.origin), d(ray.dir);
    bool in = list.startsInside;
    double before = list.count > 0 ? list[0].t - 1 : 0;
    CHECK(inside(o + LD(before) * d) == in);
    for (int i = 0; i < list.count; ++i) {
        in = !in;
        double a = list[i].t;
        double b = i + 1 < list.count ? list[i + 1].t : a + 1;
        if (b - a > 1e-6 * (1 + std::abs(a))) CHECK(inside(o + LD(0.5 * (a + b)) * d) == in);
    }
}

/// Deterministic random numbers for the randomized tests.
class Random {
  public:
    explicit Random(uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    Vec3 inBox(double half) {
        return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
    }
    /// A point uniformly within the box.
    Vec3 pointIn(const Bounds3& b) {
        return {uniform(b.lo.x, b.hi.x), uniform(b.lo.y, b.hi.y), uniform(b.lo.z, b.hi.z)};
    }
    Vec3 unit() {
        for (;;) {
            Vec3 v = inBox(1);
            double l = glm::length(v);
            if (l > 0.1 && l <= 1) return v / l;
        }
    }
    /// A line through `target` from a random origin at `distance`, with a random length scale.
    Ray lineThrough(const Vec3& target, double distance) {
        Vec3 from = target + distance * unit();
        Vec3 dir = (target - from) * uniform(0.2, 3.0) / distance;
        return {from, dir};
    }

  private:
    std::mt19937_64 engine_;
};

} // namespace crt::tracer::test
