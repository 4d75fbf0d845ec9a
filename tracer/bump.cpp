// Bump mapping by finite differences of the height field, in object space or in uv.
#include "tracer/bump.hpp"

#include <cmath>

namespace crt::tracer {

namespace {

/// The height's gradient in object space.
Vec3 pointGradient(const Texture& bump, const SurfaceInteraction& si) {
    double step = bump.slopeStep();
    double h0 = bump.height(si.objectPoint, si.uv, si.mappingAxis);
    Vec3 gradient(bump.height(si.objectPoint + Vec3(step, 0, 0), si.uv, si.mappingAxis) - h0,
                  bump.height(si.objectPoint + Vec3(0, step, 0), si.uv, si.mappingAxis) - h0,
                  bump.height(si.objectPoint + Vec3(0, 0, step), si.uv, si.mappingAxis) - h0);
    return gradient / step;
}

/// The surface vector g with g·dpdu = ∂h/∂u and g·dpdv = ∂h/∂v: the height's gradient on the
/// surface (through the inverse of the uv metric, so skewed or stretched uvs are handled).
/// Zero where the tangents do not span a plane (a sphere's pole, degenerate mesh uvs).
Vec3 uvGradient(const Texture& bump, const SurfaceInteraction& si) {
    double step = bump.slopeStep();
    double h0 = bump.height(si.objectPoint, si.uv, si.mappingAxis);
    double hu = (bump.height(si.objectPoint, si.uv + Vec2(step, 0), si.mappingAxis) - h0) / step;
    double hv = (bump.height(si.objectPoint, si.uv + Vec2(0, step), si.mappingAxis) - h0) / step;
    double e = glm::dot(si.dpdu, si.dpdu), f = glm::dot(si.dpdu, si.dpdv),
           g = glm::dot(si.dpdv, si.dpdv);
    double det = e * g - f * f;
    if (!(det > 1e-12 * e * g) || !(det > 0)) return Vec3(0.0);
    Vec3 gradient = ((g * hu - f * hv) * si.dpdu + (e * hv - f * hu) * si.dpdv) / det;
    return std::isfinite(gradient.x + gradient.y + gradient.z) ? gradient : Vec3(0.0);
}

} // namespace

Vec3 bumpedNormal(const Texture& bump, const SurfaceInteraction& si, const Vec3& n) {
    Vec3 gradient = bump.heightFromUv() ? uvGradient(bump, si) : pointGradient(bump, si);
    Vec3 tangential = gradient - glm::dot(gradient, n) * n;
    return glm::normalize(n - bump.strength() * 0.1 * tangential);
}

} // namespace crt::tracer
