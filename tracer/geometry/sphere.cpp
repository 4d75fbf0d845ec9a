// The sphere primitive: exact line crossings and refined surface points.
#include "tracer/geometry/sphere.hpp"

#include "tracer/geometry/geometry_math.hpp"

namespace crt::tracer {

SphereGeometry::SphereGeometry(const scene::SphereShape& desc)
    : center_(desc.center), radius_(desc.radius > 0 ? desc.radius : 0) {}

Bounds3 SphereGeometry::bounds() const {
    if (!(radius_ > 0)) return {};
    return padded({center_ - Vec3(radius_), center_ + Vec3(radius_)});
}

CRT_FMA_VERSIONS void SphereGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!(radius_ > 0)) return;
    const Vec3& d = ray.dir;
    double a = glm::dot(d, d);
    if (a == 0) return;
    // Solve from the line's closest approach to the centre (pbrt-v4's accurate discriminant):
    // a far origin then costs no precision beyond the rounding of that point itself.
    Vec3 f = ray.origin - center_;
    double tc = -glm::dot(f, d) / a;
    Vec3 l = f + tc * d;
    // A clear miss needs no square root. The line passes farther from the centre than the
    // radius by a relative 1e-6 of its square, which bounds the rounding of c below by far,
    // and the discriminant is below half its value: the exact computation would miss too.
    double squaredDistance = glm::dot(l, l), squaredRadius = radius_ * radius_, halfB = glm::dot(l, d);
    if (squaredDistance > squaredRadius * (1 + 1e-6) &&
        halfB * halfB < 0.5 * a * (squaredDistance - squaredRadius)) {
        return;
    }
    double len = std::sqrt(squaredDistance);
    double c = (len - radius_) * (len + radius_);
    double s0, s1;
    if (!solveQuadratic(a, halfB, c, s0, s1)) return;
    out.add(tc + s0, 0);
    out.add(tc + s1, 0);
}

SurfacePoint SphereGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    Vec3 p = ray.at(crossing.t);
    Vec3 f = p - center_;
    double len = glm::length(f);
    Vec3 n = len > 0 ? f / len : Vec3(0, 1, 0);
    double distance = len - radius_;
    // p − c rounds once per component, the length adds three more relative roundings, the
    // subtraction of the radius one more.
    double distanceError = errorGamma(6) * len + errorGamma(1) * std::abs(distance);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);

    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    if (wantUv) {
        sp.uv = {angleCoordinate(n.z, n.x),
                 clamp01(0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi)};
        // p = c + r·(cos λ cos φ, sin λ, cos λ sin φ), longitude φ = 2πu, latitude λ = π(v − ½).
        double rho = std::sqrt(n.x * n.x + n.z * n.z);
        double cosPhi = rho > 0 ? n.x / rho : 1, sinPhi = rho > 0 ? n.z / rho : 0;
        sp.dpdu = 2 * kPi * radius_ * Vec3(-n.z, 0, n.x);
        sp.dpdv = kPi * radius_ * Vec3(-n.y * cosPhi, rho, -n.y * sinPhi);
    }
    return sp;
}

} // namespace crt::tracer

namespace crt::tracer {

double SphereGeometry::area() const { return 4 * kPi * radius_ * radius_; }

AreaSample SphereGeometry::sampleArea(const Vec2& u) const {
    const double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u.y;
    const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
    return {center_ + radius_ * n, n};
}

} // namespace crt::tracer
