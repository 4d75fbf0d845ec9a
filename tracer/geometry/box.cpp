// The axis-aligned box primitive (in object space): slab crossings and per-face surface points.
#include "tracer/geometry/box.hpp"

#include "tracer/geometry/geometry_math.hpp"


namespace crt::tracer {

BoxGeometry::BoxGeometry(const scene::BoxShape& desc)
    : lo_(glm::min(desc.cornerA, desc.cornerB)), hi_(glm::max(desc.cornerA, desc.cornerB)),
      empty_(!(lo_.x < hi_.x && lo_.y < hi_.y && lo_.z < hi_.z)) {}

Bounds3 BoxGeometry::bounds() const {
    return empty_ ? Bounds3{} : Bounds3{lo_, hi_};
}

void BoxGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    LineSpan span;
    if (!lineSpan(ray, lo_, hi_, span)) return;
    out.add(span.enter, span.enterFace);
    out.add(span.exit, span.exitFace);
}

SurfacePoint BoxGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    int axis = int(crossing.part / 2) % 3;
    bool high = crossing.part % 2 == 1;
    double face = high ? hi_[axis] : lo_[axis];
    Vec3 n(0.0);
    n[axis] = high ? 1 : -1;
    Vec3 p = ray.at(crossing.t);
    double distance = high ? p[axis] - face : face - p[axis];
    RefinedPoint r = refineOntoSurface(p, distance, errorGamma(1) * std::abs(distance), n);
    // The face plane is representable: snap onto it exactly. Clamping the other coordinates
    // into the face then leaves the point on the exact surface, within its bound.
    r.point[axis] = face;
    r.error[axis] = 0;
    int ua = (axis + 1) % 3, va = (axis + 2) % 3;
    r.point[ua] = std::clamp(r.point[ua], lo_[ua], hi_[ua]);
    r.point[va] = std::clamp(r.point[va], lo_[va], hi_[va]);

    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    sp.uv = {clamp01((r.point[ua] - lo_[ua]) / (hi_[ua] - lo_[ua])),
             clamp01((r.point[va] - lo_[va]) / (hi_[va] - lo_[va]))};
    sp.dpdu[ua] = hi_[ua] - lo_[ua];
    sp.dpdv[va] = hi_[va] - lo_[va];
    return sp;
}

} // namespace crt::tracer
