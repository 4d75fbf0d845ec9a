// Patterns of an angle: around an axis, and the surface's against a direction.
#include "tracer/patterns/pattern_functions.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace crt::tracer::patterns {

double radial(const Vec3& p) {
    // The angle around y as a fraction of a turn, with POV-Ray's quarter-turn offset.
    if (std::abs(p.x) < 0.001 && std::abs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + kPi) / (2 * kPi);
}

double spiral(const Vec3& p, int arms) {
    // POV-Ray's spiral1: around z, advancing one unit along z per turn of each arm.
    double radius = std::sqrt(p.x * p.x + p.y * p.y);
    double angle = 0;
    if (radius != 0) {
        angle = p.x < 0 ? 1.5 * kPi - std::asin(p.y / radius) : 0.5 * kPi + std::asin(p.y / radius);
    }
    return p.z + radius + arms * angle / (2 * kPi);
}

double slope(const Vec3& normal, const Vec3& direction) {
    // The angle between the surface and the plane across `direction`, from -90° (facing away)
    // through 0 (upright) to 90° (facing it), as 0 to 1 (POV-Ray's slope).
    double cosine = std::clamp(glm::dot(normal, glm::normalize(direction)), -1.0, 1.0);
    return (std::asin(cosine) / kPi * 2 + 1) * 0.5;
}

} // namespace crt::tracer::patterns
