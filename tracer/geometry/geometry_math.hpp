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

inline double clamp01(double x) {
    return std::clamp(x, 0.0, 1.0);
}

/// A surface point and a per-component bound of its distance to the exact hit.
struct RefinedPoint {
    Vec3 point;
    Vec3 error;
};

/// Moves the computed line point p ≈ o + t·d onto the surface along the unit normal n.
///
/// `distance` is the signed distance of p from the surface (positive on n's side) as computed,
/// `distanceError` a bound of its rounding error, `cap` a bound on how far apart two points of
/// the shape can be. The returned bound covers the exact crossing of the exact line with the
/// exact surface, to first order. The computed p is off the exact line point o + t·d by δ, the
/// rounding of o + t·d; that exact point is within `away` = |distance| + distanceError + |n·δ|
/// of the surface, so the exact crossing lies Δt = away / |n·d| along the line. Moving p along
/// n leaves the point off the crossing by the tangential parts of δ and of Δt·d, and a
/// tangential vector v has per-axis components at most |v_i| + |n·v|·|n_i|; |n·Δt·d| ≤ away.
/// A factor 2 covers the second-order (curvature) terms and the rounding of n itself.
inline RefinedPoint refineOntoSurface(const Ray& ray, double t, const Vec3& p, double distance,
                                      double distanceError, const Vec3& n, double cap) {
    Vec3 an = absolute(n);
    Vec3 ad = absolute(ray.dir);
    Vec3 evalError = errorGamma(2) * (absolute(ray.origin) + absolute(t * ray.dir));
    double away = std::abs(distance) + distanceError + glm::dot(an, evalError);
    double nd = std::abs(glm::dot(n, ray.dir));
    double slide = nd > 0 ? away / nd : kInfinity;
    Vec3 point = p - distance * n;
    Vec3 moveError = errorGamma(2) * (absolute(p) + std::abs(distance) * an);
    Vec3 error;
    for (int i = 0; i < 3; ++i) {
        double along = ad[i] > 0 ? std::min(slide * ad[i], cap) : 0.0;
        error[i] = 2 * (evalError[i] + moveError[i] + along + std::min(2 * away, cap) * an[i]);
    }
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
