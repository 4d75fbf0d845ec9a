// The centre and axis that spherical and cylindrical image mappings wrap around.
#include "tracer/geometry/mapping_axis.hpp"

namespace crt::tracer {

Vec3 MappingAxis::toAxisSpace(const Vec3& p) const {
    Vec3 q = p - origin;
    // Rodrigues' rotation taking the unit `axis` to +y, in the form without normalising its
    // rotation axis k = axis × y: q' = q·c + k × q + k·(k·q)/(1 + c), c = axis · y.
    double c = axis.y;
    if (c >= 1) return q;
    if (c <= -1 + 1e-12) return {q.x, -q.y, -q.z}; // upside down: half a turn about x
    Vec3 k(-axis.z, 0, axis.x);
    return q * c + glm::cross(k, q) + k * (glm::dot(k, q) / (1 + c));
}

} // namespace crt::tracer
