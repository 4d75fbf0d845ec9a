// The infinite plane primitive; as a solid, the half-space behind its normal.
#include "tracer/geometry/plane.hpp"

namespace crt::tracer {

PlaneGeometry::PlaneGeometry(const scene::PlaneShape& desc) : position_(desc.position) {
    double len = glm::length(desc.normal);
    empty_ = !(len > 0) || !std::isfinite(len);
    frame_ = Frame::fromAxis(empty_ ? Vec3(0, 1, 0) : desc.normal / len);
}

void PlaneGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    double nd = glm::dot(frame_.w, ray.dir);
    double s = glm::dot(frame_.w, ray.origin - position_);
    double t = nd != 0 ? -s / nd : kInfinity;
    if (!std::isfinite(t)) {
        out.startsInside = s <= 0;
        return;
    }
    // Coming from t = −∞ the line is behind the plane exactly when it moves toward the front.
    out.startsInside = nd > 0;
    out.add(t, 0);
}

SurfacePoint PlaneGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    const Vec3& n = frame_.w;
    Vec3 p = ray.at(crossing.t);
    Vec3 rel = p - position_;
    double distance = glm::dot(n, rel);
    // The subtraction and the dot product round a few times relative to |p| + |position|.
    // Normalising rounds each component of n once (a wrong length only scales the distance,
    // covered by the last term): the plane tilts by one rounding of n_i per axis, which moves
    // it by that much times the distance from `position` along that axis.
    double distanceError =
        errorGamma(6) * glm::dot(absolute(n), absolute(p) + absolute(position_)) +
        errorGamma(2) * glm::dot(absolute(n), absolute(rel)) + errorGamma(3) * std::abs(distance);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    Vec3 onPlane = r.point - position_;
    sp.uv = {glm::dot(onPlane, frame_.u), glm::dot(onPlane, frame_.v)};
    sp.dpdu = frame_.u;
    sp.dpdv = frame_.v;
    return sp;
}

} // namespace crt::tracer
