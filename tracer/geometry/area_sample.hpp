// Points drawn uniformly by area on a surface: where the path integrator aims at an emitting
// shape.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <cmath>

namespace crt::tracer {

/// A point of a surface and its unit normal there (outward for solids), in object space.
struct AreaSample {
    Vec3 point{0.0};
    Vec3 normal{0, 1, 0};
};

inline double triangleArea(const Vec3 (&p)[3]) { return 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])); }

/// A point of the triangle, uniform by area for u uniform in [0, 1)² (the square-root warp).
inline AreaSample sampleTriangle(const Vec3 (&p)[3], const Vec2& u) {
    const double s = std::sqrt(u.x);
    const double a = 1 - s, b = u.y * s;
    const Vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(n);
    return {a * p[0] + b * p[1] + (1 - a - b) * p[2], len > 0 ? n / len : Vec3(0, 1, 0)};
}

} // namespace crt::tracer
