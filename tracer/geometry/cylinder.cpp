// The finite cylinder primitive (capped, or open and then not a solid).
#include "tracer/geometry/cylinder.hpp"

namespace crt::tracer {

CylinderGeometry::CylinderGeometry(const scene::CylinderShape& desc)
    : solid_(desc.base, desc.top, desc.radius, desc.radius, desc.open) {}

SurfacePoint CylinderGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    return solid_.surfaceAt(ray, crossing, wantUv);
}

} // namespace crt::tracer
