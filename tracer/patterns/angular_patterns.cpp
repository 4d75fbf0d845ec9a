// Patterns of the angle around an axis.
#include "tracer/patterns/pattern_functions.hpp"

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

} // namespace crt::tracer::patterns
