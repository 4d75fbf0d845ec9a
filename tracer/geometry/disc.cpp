// The disc primitive (with an optional hole: an annulus); a surface, not a solid.
#include "tracer/geometry/disc.hpp"

namespace crt::tracer {

DiscGeometry::DiscGeometry(const scene::DiscShape& desc) : center_(desc.center) {
    double len = glm::length(desc.normal);
    radius_ = desc.radius > 0 ? desc.radius : 0;
    hole_ = desc.hole > 0 ? desc.hole : 0;
    empty_ = !(radius_ > hole_) || !(len > 0) || !std::isfinite(len);
    frame_ = Frame::fromAxis(empty_ ? Vec3(0, 1, 0) : desc.normal / len);
}

Bounds3 DiscGeometry::bounds() const {
    if (empty_) return {};
    const Vec3& w = frame_.w;
    Vec3 e = radius_ * glm::sqrt(glm::max(Vec3(1.0) - w * w, Vec3(0.0)));
    return padded({center_ - e, center_ + e});
}

void DiscGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    double nd = glm::dot(frame_.w, ray.dir);
    if (nd == 0) return;
    double t = glm::dot(frame_.w, center_ - ray.origin) / nd;
    if (!std::isfinite(t)) return;
    Vec3 rel = ray.at(t) - center_;
    // Measured in the plane (the normal component is only rounding).
    double x = glm::dot(rel, frame_.u), y = glm::dot(rel, frame_.v);
    double r2 = x * x + y * y;
    if (r2 <= radius_ * radius_ && r2 >= hole_ * hole_) out.add(t, 0);
}

SurfacePoint DiscGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const Vec3& n = frame_.w;
    Vec3 p = ray.at(crossing.t);
    Vec3 rel = p - center_;
    double distance = glm::dot(n, rel);
    // As the plane's: rounding relative to |p| + |centre|, and the normalised normal's tilt (one
    // rounding per component) times the distance from the centre along each axis.
    double distanceError = errorGamma(6) * glm::dot(absolute(n), absolute(p) + absolute(center_)) +
                           errorGamma(2) * glm::dot(absolute(n), absolute(rel)) +
                           errorGamma(3) * std::abs(distance);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    if (wantUv) {
        Vec3 onPlane = r.point - center_;
        double x = glm::dot(onPlane, frame_.u), y = glm::dot(onPlane, frame_.v);
        double rho = std::sqrt(x * x + y * y);
        sp.uv = {angleCoordinate(y, x), clamp01(rho / radius_)};
        // p = centre + v·radius·(cos 2πu, sin 2πu) in the frame's (u, v) plane.
        sp.dpdu = 2 * kPi * (x * frame_.v - y * frame_.u);
        sp.dpdv = rho > 0 ? radius_ / rho * (x * frame_.u + y * frame_.v) : radius_ * frame_.u;
    }
    return sp;
}

} // namespace crt::tracer

namespace crt::tracer {

double DiscGeometry::area() const { return empty_ ? 0 : kPi * (radius_ * radius_ - hole_ * hole_); }

AreaSample DiscGeometry::sampleArea(const Vec2& u) const {
    const double r = std::sqrt(hole_ * hole_ + u.x * (radius_ * radius_ - hole_ * hole_)), phi = 2 * kPi * u.y;
    return {center_ + r * (std::cos(phi) * frame_.u + std::sin(phi) * frame_.v), frame_.w};
}

} // namespace crt::tracer
