// The polygon primitive: POV-Ray's, loops with holes in one plane; a surface, not a solid.
#include "tracer/geometry/polygon.hpp"

#include "scene/polygon_loops.hpp"

namespace crt::tracer {

PolygonGeometry::PolygonGeometry(const scene::PolygonShape& desc) {
    const std::vector<std::vector<Vec3>> loops = scene::polygonLoops(desc.points);
    if (loops.empty() || loops.front().size() < 3) return;
    const Vec3 newell = scene::newellNormal(loops.front());
    const double len = glm::length(newell);
    if (!(len > 0) || !std::isfinite(len)) return;
    normal_ = newell / len;
    origin_ = loops.front().front();
    // Each Newell term is a product of a difference and a sum, added up over the loop: the
    // rounding of every term, relative to the sum of their sizes, tilts the normal.
    Vec3 size(0.0);
    for (const Vec3& p : loops.front()) size += absolute(p);
    tilt_ = errorGamma(4 + 2 * static_cast<int>(loops.front().size())) *
                (Vec3(size.y * size.z, size.z * size.x, size.x * size.y) * 4.0) / len +
            errorGamma(2) * absolute(normal_);
    const Vec3 an = absolute(normal_);
    dropped_ = an.x > an.y ? (an.x > an.z ? 0 : 2) : (an.y > an.z ? 1 : 2);
    std::vector<std::vector<Vec2>> flat;
    for (const std::vector<Vec3>& loop : loops) {
        std::vector<Vec2>& f = flat.emplace_back();
        for (const Vec3& p : loop) {
            f.push_back(project(p));
            bounds_.include(p);
        }
    }
    outline_ = std::make_shared<const Outline>(flat);
    bounds_ = padded(bounds_);
}

Vec2 PolygonGeometry::project(const Vec3& p) const {
    return {p[(dropped_ + 1) % 3], p[(dropped_ + 2) % 3]};
}

void PolygonGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!outline_) return;
    const double nd = glm::dot(normal_, ray.dir);
    if (nd == 0) return;
    const double t = glm::dot(normal_, origin_ - ray.origin) / nd;
    if (!std::isfinite(t)) return;
    if (outline_->contains(project(ray.at(t)))) out.add(t, 0);
}

SurfacePoint PolygonGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    const Vec3& n = normal_;
    const Vec3 p = ray.at(crossing.t);
    const Vec3 rel = p - origin_;
    const double distance = glm::dot(n, rel);
    const double distanceError =
        errorGamma(6) * glm::dot(absolute(n), absolute(p) + absolute(origin_)) +
        glm::dot(tilt_, absolute(rel)) + errorGamma(3) * std::abs(distance);
    const RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    const Frame frame = Frame::fromAxis(n);
    const Vec3 onPlane = r.point - origin_;
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    sp.uv = {glm::dot(onPlane, frame.u), glm::dot(onPlane, frame.v)};
    sp.dpdu = frame.u;
    sp.dpdv = frame.v;
    return sp;
}

} // namespace crt::tracer
