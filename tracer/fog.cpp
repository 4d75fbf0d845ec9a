// Fog, as POV-Ray's fog: constant, or ground fog whose density 1/(1 + h²) is integrated
// along the ray in closed form (atan), with turbulence thinning it by a noise at the
// stretch's middle, less so the deeper the fog.
#include "tracer/fog.hpp"

#include "tracer/lights.hpp"
#include "tracer/noise.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// How far a ray that meets nothing is taken to cross the fog: far enough that a constant
/// fog hides the background entirely and ground fog has reached its limit.
constexpr double kFarDistance = 2e10;
constexpr int kTurbulenceOctaves = 6;

} // namespace

Fog::Fog(const scene::FogDesc& desc)
    : desc_(desc), color_(rgb(desc.color)), leastSeen_(std::clamp(1 - desc.color.a, 0.0, 1.0)) {}

double Fog::meanGroundDensity(double a, double b) {
    // ∫ density dh over [a, b] / (b − a), with density 1 below 0 and 1/(1 + h²) above.
    if (a > b) std::swap(a, b);
    if (b <= 0) return 1;
    if (a <= 0) return (std::atan(b) - a) / (b - a);
    if (b - a > 1e-10) return (std::atan(b) - std::atan(a)) / (b - a);
    return 1 / (a * a + 1);
}

FogCrossing Fog::along(const Ray& ray, double distance) const {
    double depth = std::min(distance, kFarDistance);
    double density = 1;
    if (desc_.falloff > 0) {
        const double start = glm::dot(ray.origin, desc_.up), end = start + depth * glm::dot(ray.dir, desc_.up);
        density = meanGroundDensity((start - desc_.altitude) / desc_.falloff, (end - desc_.altitude) / desc_.falloff);
    }
    if (desc_.turbulence != Vec3(0.0)) {
        const Vec3 middle = (ray.origin + ray.dir * (depth / 2)) * desc_.turbulence;
        const double nearness = std::exp(-depth / desc_.distance);
        depth *= 1 - nearness * std::min(1.0, turbulence(middle, kTurbulenceOctaves) * desc_.turbulenceDepth);
    }
    const double seen = std::max(std::exp(-depth * density / desc_.distance), leastSeen_);
    FogCrossing crossing;
    crossing.transmittance = seen * ((1 - desc_.filter) + desc_.filter * color_);
    crossing.inscattered = (1 - seen) * color_;
    return crossing;
}

} // namespace crt::tracer
