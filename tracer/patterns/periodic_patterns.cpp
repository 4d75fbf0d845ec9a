// Patterns that repeat each unit cell of space.
#include "tracer/patterns/pattern_functions.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace crt::tracer::patterns {

double leopard(const Vec3& p) {
    double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3;
    return s * s;
}

double quilted(const Vec3& p, double control0, double control1) {
    // Each cell's offset from its centre, scaled by a cubic Bezier of its length whose inner
    // control points are control0 and control1 (POV-Ray's quilted).
    Vec3 v = p - glm::floor(p) - Vec3(0.5);
    double t = glm::length(v), it = 1 - t;
    double bezier =
        (t * t * t + 3 * t * it * it * control0 + 3 * t * t * it * control1) * 1.154700538;
    v *= bezier;
    return (std::abs(v.x) + std::abs(v.y) + std::abs(v.z)) / 3;
}

} // namespace crt::tracer::patterns
