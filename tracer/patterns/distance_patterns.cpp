// Patterns of a distance: along an axis, from the origin, from the y axis, from a plane.
#include "tracer/patterns/pattern_functions.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace crt::tracer::patterns {

namespace {

/// 1 at distance 0, falling to 0 at distance 1 and beyond (POV-Ray's density fall-off).
double fallOff(double distance) {
    return distance > 1 ? 0 : 1 - distance;
}

} // namespace

double gradient(const Vec3& p, const Vec3& axis) {
    double along = glm::dot(p, glm::normalize(axis));
    return along > 1 ? std::fmod(along, 1.0) : along;
}

double onion(const Vec3& p) {
    return std::fmod(glm::length(p), 1.0);
}

double boxed(const Vec3& p) {
    return fallOff(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
}

double spherical(const Vec3& p) {
    return fallOff(glm::length(p));
}

double cylindrical(const Vec3& p) {
    return fallOff(std::sqrt(p.x * p.x + p.z * p.z));
}

double planar(const Vec3& p) {
    return fallOff(std::abs(p.y));
}

} // namespace crt::tracer::patterns
