// Rays, the floating-point error bound helpers and the small vector aliases the renderer uses.
//
// Geometry is computed in double precision; spawned rays are offset by a bound on the hit
// point's rounding error (pbrt's "Managing Rounding Error"), never by a fixed epsilon.
#pragma once

#include <glm/glm.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace crt::tracer {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4; ///< a colour with its alpha

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// The fractional part x − ⌊x⌋, in [0, 1) (also for negative x, unlike std::modf).
inline double fract(double x) {
    return x - std::floor(x);
}

/// pbrt's gamma(n) = n·u / (1 − n·u): bounds the relative error of n chained roundings.
constexpr double errorGamma(int n) {
    constexpr double unitRoundoff = std::numeric_limits<double>::epsilon() * 0.5;
    return (n * unitRoundoff) / (1 - n * unitRoundoff);
}

/// A ray o + t·d. The direction need not be unit length (object-space rays keep the world
/// ray's t, so hits found in any space compare directly).
struct Ray {
    Vec3 origin{0.0};
    Vec3 dir{0, 0, 1};
    /// When the ray is cast while the shutter is open: 0 as it opens, 1 as it closes (what
    /// moves is where it is then; motion.hpp).
    double time = 0;

    Vec3 at(double t) const { return origin + t * dir; }
};

/// |v| per component, without branches (glm::abs compares and negates each component of a
/// double vector, which costs mispredicted branches in the hot paths that bound rounding).
inline Vec3 absolute(const Vec3& v) {
    return {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
}

/// The next representable double above / below v (pbrt's NextFloatUp/Down, without libm's
/// call: this runs for every spawned ray).
inline double nextUp(double v) {
    if (std::isinf(v) && v > 0) return v;
    if (v == -0.0) v = 0.0;
    uint64_t bits = std::bit_cast<uint64_t>(v);
    bits = v >= 0 ? bits + 1 : bits - 1;
    return std::bit_cast<double>(bits);
}
inline double nextDown(double v) {
    if (std::isinf(v) && v < 0) return v;
    if (v == 0.0) v = -0.0;
    uint64_t bits = std::bit_cast<uint64_t>(v);
    bits = v > 0 ? bits - 1 : bits + 1;
    return std::bit_cast<double>(bits);
}

/// Moves a surface point off the surface by its error bound, to the side `w` points to,
/// so a ray spawned from it cannot hit the same surface again.
inline Vec3 offsetRayOrigin(const Vec3& point, const Vec3& pointError, const Vec3& normal, const Vec3& w) {
    double distance = glm::dot(absolute(normal), pointError);
    Vec3 offset = distance * normal;
    if (glm::dot(w, normal) < 0) offset = -offset;
    Vec3 origin = point + offset;
    // Round away from the point so the offset is not lost to rounding.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0) origin[i] = nextUp(origin[i]);
        else if (offset[i] < 0) origin[i] = nextDown(origin[i]);
    }
    return origin;
}

} // namespace crt::tracer
