// The triangle primitive: watertight line crossing in double; a surface, not a solid.
#include "tracer/geometry/triangle.hpp"

namespace crt::tracer {

TriangleGeometry::TriangleGeometry(const scene::TriangleShape& desc) : p_{desc.a, desc.b, desc.c} {
    Vec3 e1 = p_[1] - p_[0], e2 = p_[2] - p_[0];
    Vec3 nn = glm::cross(e1, e2);
    double len = glm::length(nn);
    empty_ = !(len > 0) || !std::isfinite(len);
    if (empty_) return;
    normal_ = nn / len;
    // The edges round once per component; each cross-product component is a difference of two
    // products rounded relative to their magnitudes. Relative to |N| that tilts the normal (an
    // error in its length only scales distances).
    Vec3 crossError(std::abs(e1.y * e2.z) + std::abs(e1.z * e2.y),
                    std::abs(e1.z * e2.x) + std::abs(e1.x * e2.z),
                    std::abs(e1.x * e2.y) + std::abs(e1.y * e2.x));
    tilt_ = errorGamma(6) * crossError / len + errorGamma(2) * absolute(normal_);
}

Bounds3 TriangleGeometry::bounds() const {
    if (empty_) return {};
    Bounds3 b = Bounds3::of(p_[0], p_[1]);
    b.include(p_[2]);
    return b; // the vertices themselves: exact
}

bool crossTriangle(const Vec3 (&p)[3], const Ray& ray, double& t, Vec3& weights) {
    // Translate to the origin, permute so the direction's largest component is z, and shear
    // the direction onto +z: the test becomes 2D edge functions at (0, 0), evaluated the same
    // way for an edge shared by two triangles.
    Vec3 ad = absolute(ray.dir);
    int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    if (ray.dir[kz] == 0) return false;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    double dz = ray.dir[kz];
    double sx = -ray.dir[kx] / dz, sy = -ray.dir[ky] / dz, sz = 1 / dz;
    double x[3], y[3], z[3];
    for (int i = 0; i < 3; ++i) {
        Vec3 q = p[i] - ray.origin;
        x[i] = q[kx] + sx * q[kz];
        y[i] = q[ky] + sy * q[kz];
        z[i] = q[kz] * sz;
    }
    double e0 = differenceOfProducts(x[1], y[2], y[1], x[2]);
    double e1 = differenceOfProducts(x[2], y[0], y[2], x[0]);
    double e2 = differenceOfProducts(x[0], y[1], y[0], x[1]);
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
    double det = e0 + e1 + e2;
    if (det == 0) return false; // parallel, or through a point of the line only
    t = (e0 * z[0] + e1 * z[1] + e2 * z[2]) / det;
    weights = Vec3(e0, e1, e2) / det;
    return std::isfinite(t);
}

bool TriangleGeometry::intersect(const Ray& ray, double& t, Vec3& weights) const {
    return !empty_ && crossTriangle(p_, ray, t, weights);
}

CRT_FMA_VERSIONS void TriangleGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    double t;
    Vec3 weights;
    if (intersect(ray, t, weights)) out.add(t, 0);
}

Vec3 TriangleGeometry::barycentrics(const Ray& ray, const Crossing& crossing) const {
    double t;
    Vec3 weights;
    if (intersect(ray, t, weights)) return weights;
    // Not the line that crossed (or a degenerate case): solve from the point in the plane.
    Vec3 e1 = p_[1] - p_[0], e2 = p_[2] - p_[0], rel = ray.at(crossing.t) - p_[0];
    double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    double r1 = glm::dot(rel, e1), r2 = glm::dot(rel, e2);
    double det = differenceOfProducts(d11, d22, d12, d12);
    if (!(det > 0)) return {1, 0, 0};
    double b1 = clamp01(differenceOfProducts(d22, r1, d12, r2) / det);
    double b2 = clamp01(differenceOfProducts(d11, r2, d12, r1) / det);
    return {1 - b1 - b2, b1, b2};
}

SurfacePoint TriangleGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const Vec3& n = normal_;
    Vec3 p = ray.at(crossing.t);
    Vec3 rel = p - p_[0];
    double distance = glm::dot(n, rel);
    double distanceError = errorGamma(6) * glm::dot(absolute(n), absolute(p) + absolute(p_[0])) +
                           glm::dot(tilt_, absolute(rel)) + errorGamma(3) * std::abs(distance);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    if (wantUv) {
        // The weights come from the crossing's test again: worth it only for a surface read.
        const Vec3 b = barycentrics(ray, crossing);
        sp.uv = {clamp01(b.y), clamp01(b.z)};
    }
    // p = a + u·(b − a) + v·(c − a).
    sp.dpdu = p_[1] - p_[0];
    sp.dpdv = p_[2] - p_[0];
    return sp;
}

} // namespace crt::tracer

namespace crt::tracer {

double TriangleGeometry::area() const { return empty_ ? 0 : triangleArea(p_); }

AreaSample TriangleGeometry::sampleArea(const Vec2& u) const { return sampleTriangle(p_, u); }

} // namespace crt::tracer
