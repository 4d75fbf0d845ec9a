// The finite cone (frustum) primitive (capped, or open and then not a solid).
#include "tracer/geometry/cone.hpp"

namespace crt::tracer {

ConeGeometry::ConeGeometry(const scene::ConeShape& desc)
    : solid_(desc.base, desc.top, desc.baseRadius, desc.topRadius, desc.open) {}

SurfacePoint ConeGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    return solid_.surfaceAt(ray, crossing, wantUv);
}

} // namespace crt::tracer
