// Numerics shared by the primitives: stable quadratic roots, orthonormal frames, angles as
// texture coordinates, and moving a line point onto a surface with a bound of its error.
#pragma once

#include "tracer/geometry/shape.hpp"

#include <algorithm>
#include <cmath>

/// Put on the hot functions whose accuracy rests on std::fma: they get a second version for
/// processors with the FMA instruction, picked when the program loads, in which std::fma is
/// that instruction instead of a call into libm. Both give the same bits: fma rounds once
/// either way, and the build never fuses anything else (-ffp-contract=off).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__FMA__)
#define CRT_FMA_VERSIONS [[gnu::target_clones("fma", "default")]]
#else
#define CRT_FMA_VERSIONS
#endif

namespace crt::tracer {

/// a·b − c·d with about one rounding of error (Kahan's fma algorithm): a discriminant near
/// zero keeps its sign instead of drowning in the cancellation of two large products.
inline double differenceOfProducts(double a, double b, double c, double d) {
    double cd = c * d;
    double err = std::fma(-c, d, cd);
    double dop = std::fma(a, b, -cd);
    return dop + err;
}

/// The real roots of a·t² + 2·halfB·t + c = 0 (a ≠ 0), ascending; false when there are none.
/// A double root is returned twice, so a tangent line crosses a solid zero or two times.
/// Uses q = −(halfB + sign(halfB)·√disc), t = q/a and c/q: no cancellation between −b and √disc.
inline bool solveQuadratic(double a, double halfB, double c, double& t0, double& t1) {
    if (a == 0) return false;
    double disc = differenceOfProducts(halfB, halfB, a, c);
    if (!(disc >= 0)) return false; // also rejects NaN
    double q = -(halfB + std::copysign(std::sqrt(disc), halfB));
    if (q == 0) { // halfB = disc = 0 forces c = 0: a double root at 0
        t0 = t1 = 0;
        return true;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return std::isfinite(t0) && std::isfinite(t1);
}

inline double sumAbs(const Vec3& v) {
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}

/// An orthonormal frame (u, v, w) around a unit axis w; Duff et al.'s branchless construction,
/// so the frame is a continuous, deterministic function of the axis.
struct Frame {
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
    Vec3 w{0, 0, 1};

    static Frame fromAxis(const Vec3& w) {
        double sign = std::copysign(1.0, w.z);
        double a = -1 / (sign + w.z);
        double b = w.x * w.y * a;
        return {Vec3(1 + sign * w.x * w.x * a, sign * b, -sign * w.x),
                Vec3(b, sign + w.y * w.y * a, -w.y), w};
    }
    Vec3 toLocal(const Vec3& p) const { return {glm::dot(p, u), glm::dot(p, v), glm::dot(p, w)}; }
    Vec3 fromLocal(const Vec3& p) const { return p.x * u + p.y * v + p.z * w; }
};

/// An angle atan2(y, x) as a texture coordinate in [0, 1), counter-clockwise from +x.
inline double angleCoordinate(double y, double x) {
    double a = std::atan2(y, x) * (0.5 / kPi);
    if (a < 0) a += 1;
    return a < 1 ? a : 0; // −tiny + 1 rounds to 1
}

/// A function's value and its derivative at one point.
struct ValueAndSlope {
    double value, slope;
};

/// A root of f in [lo, hi], where f(lo) and f(hi) differ in sign (negative against
/// non-negative); `f` returns f and f' at a point. Newton steps, replaced by bisection
/// whenever they would leave the bracket, so it always converges, quadratically once close.
/// The tolerance is absolute: callers scale their coordinates to about 1.
template <class F> double bracketedRoot(const F& f, double lo, double hi, bool negativeAtLo) {
    constexpr double kTolerance = 0x1p-51;
    double x = 0.5 * (lo + hi);
    for (int i = 0; i < 128; ++i) {
        const ValueAndSlope fx = f(x);
        if (fx.value == 0) return x;
        if ((fx.value < 0) == negativeAtLo)
            lo = x;
        else
            hi = x;
        double next = x - fx.value / fx.slope;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - x) <= kTolerance || hi - lo <= kTolerance) return next;
        x = next;
    }
    return x;
}

inline double clamp01(double x) {
    return std::clamp(x, 0.0, 1.0);
}

/// A surface point and a per-component bound of its distance to the exact surface.
struct RefinedPoint {
    Vec3 point;
    Vec3 error;
};

/// Moves the computed line point p onto the surface along the unit normal n.
///
/// `distance` is the signed distance of p from the surface (positive on n's side) as computed
/// from p itself, `distanceError` a bound of its rounding error. As in pbrt-v4, the returned
/// bound is a box around the point that holds a point of the exact surface (the nearest one),
/// so moving a spawned ray's origin by the box projected onto n clears the surface. It does not
/// hold the exact line's crossing: that lies off along the line by the error in t, which for a
/// line at a grazing angle is 1/|n·d| times the distance it stands for, almost along the
/// surface; projected onto n it would push a spawned ray through a surface close by.
///
/// After the move the point is off the surface by at most distanceError, plus the rounding of
/// the move and, where n is the gradient at p and not at the nearest point, a curvature term
/// below |distance|: `away` bounds both. That remainder points along n up to a tiny angle
/// (n's own rounding, and the curvature times the distance), which kTilt bounds generously;
/// the factor 2 covers the rounding of this bound and second-order terms.
inline RefinedPoint refineOntoSurface(const Vec3& p, double distance, double distanceError,
                                      const Vec3& n) {
    constexpr double kTilt = 1e-6;
    Vec3 an = absolute(n);
    double away = std::abs(distance) + distanceError;
    Vec3 point = p - distance * n;
    Vec3 moveError = errorGamma(2) * (absolute(p) + std::abs(distance) * an);
    Vec3 error = 2.0 * (moveError + away * (an + Vec3(kTilt)));
    return {point, error};
}

/// Widens bounds by a relative margin, so rounding in computing them never clips the shape.
inline Bounds3 padded(Bounds3 b) {
    if (b.empty()) return b;
    double scale = std::max(sumAbs(b.lo), sumAbs(b.hi));
    Vec3 pad(errorGamma(16) * scale);
    return {b.lo - pad, b.hi + pad};
}

} // namespace crt::tracer
