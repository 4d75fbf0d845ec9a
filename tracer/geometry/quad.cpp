// The quad primitive: a bounded parallelogram; a surface, not a solid.
#include "tracer/geometry/quad.hpp"

namespace crt::tracer {

QuadGeometry::QuadGeometry(const scene::QuadShape& desc)
    : corner_(desc.corner), edgeA_(desc.edgeA), edgeB_(desc.edgeB) {
    Vec3 nn = glm::cross(edgeA_, edgeB_);
    double len2 = glm::dot(nn, nn);
    empty_ = !(len2 > 0) || !std::isfinite(len2);
    if (empty_) return;
    double len = std::sqrt(len2);
    normal_ = nn / len;
    // (p − c) = α·A + β·B  ⇒  α = (p − c)·(B × N)/|N|², β = (p − c)·(N × A)/|N|².
    toAlpha_ = glm::cross(edgeB_, nn) / len2;
    toBeta_ = glm::cross(nn, edgeA_) / len2;
    // Each cross-product component is a difference of two products, rounded relative to their
    // magnitudes; relative to |N| that error tilts the normal.
    Vec3 crossError(std::abs(edgeA_.y * edgeB_.z) + std::abs(edgeA_.z * edgeB_.y),
                    std::abs(edgeA_.z * edgeB_.x) + std::abs(edgeA_.x * edgeB_.z),
                    std::abs(edgeA_.x * edgeB_.y) + std::abs(edgeA_.y * edgeB_.x));
    tilt_ = errorGamma(4) * crossError / len + errorGamma(2) * absolute(normal_);
}

Bounds3 QuadGeometry::bounds() const {
    if (empty_) return {};
    Bounds3 b = Bounds3::of(corner_, corner_ + edgeA_);
    b.include(corner_ + edgeB_);
    b.include(corner_ + edgeA_ + edgeB_);
    return padded(b);
}

void QuadGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    double nd = glm::dot(normal_, ray.dir);
    if (nd == 0) return;
    double t = glm::dot(normal_, corner_ - ray.origin) / nd;
    if (!std::isfinite(t)) return;
    Vec3 rel = ray.at(t) - corner_;
    double alpha = glm::dot(toAlpha_, rel), beta = glm::dot(toBeta_, rel);
    if (alpha >= 0 && alpha <= 1 && beta >= 0 && beta <= 1) out.add(t, 0);
}

SurfacePoint QuadGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    const Vec3& n = normal_;
    Vec3 p = ray.at(crossing.t);
    Vec3 rel = p - corner_;
    double distance = glm::dot(n, rel);
    double distanceError = errorGamma(6) * glm::dot(absolute(n), absolute(p) + absolute(corner_)) +
                           glm::dot(tilt_, absolute(rel)) + errorGamma(3) * std::abs(distance);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    Vec3 onPlane = r.point - corner_;
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    sp.uv = {clamp01(glm::dot(toAlpha_, onPlane)), clamp01(glm::dot(toBeta_, onPlane))};
    sp.dpdu = edgeA_;
    sp.dpdv = edgeB_;
    return sp;
}

} // namespace crt::tracer

namespace crt::tracer {

double QuadGeometry::area() const { return empty_ ? 0 : glm::length(glm::cross(edgeA_, edgeB_)); }

AreaSample QuadGeometry::sampleArea(const Vec2& u) const { return {corner_ + u.x * edgeA_ + u.y * edgeB_, normal_}; }

} // namespace crt::tracer
