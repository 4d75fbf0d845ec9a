// Media: density, coefficients and the three phase functions.
#include "tracer/medium.hpp"

#include "tracer/geometry/geometry_math.hpp"
#include "tracer/lights.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Medium::Medium(const scene::MediumDesc& desc)
    : absorption_(rgb(desc.absorption)), scattering_(rgb(desc.scattering)), emission_(rgb(desc.emission)),
      density_(desc.density), phase_(desc.phase), g_(desc.g), samples_(std::max(desc.samples, 1)) {
    if (!desc.densityPattern.empty()) pattern_.emplace(desc.densityPattern.front(), nullptr);
}

double Medium::density(const Vec3& p) const {
    if (!pattern_) return density_;
    return density_ * std::clamp(pattern_->value(p, Vec3(0, 1, 0)), 0.0, 1.0);
}

double Medium::phase(double cosTheta) const {
    switch (phase_) {
    case scene::PhaseFunction::Isotropic: return 1 / (4 * kPi);
    case scene::PhaseFunction::Rayleigh: return 3 / (16 * kPi) * (1 + cosTheta * cosTheta);
    case scene::PhaseFunction::HenyeyGreenstein: {
        const double denominator = 1 + g_ * g_ - 2 * g_ * cosTheta;
        return (1 - g_ * g_) / (4 * kPi * denominator * std::sqrt(denominator));
    }
    }
    return 1 / (4 * kPi);
}

namespace {

/// cos θ drawn by the phase function's density over it (2π·phase(cos θ)).
double sampleCosine(scene::PhaseFunction phase, double g, double u) {
    switch (phase) {
    case scene::PhaseFunction::Isotropic: break;
    case scene::PhaseFunction::Rayleigh: {
        // The cumulative (3c + c³)/8 + 1/2 = u: the cubic c³ + 3c − 2b = 0, b = 4u − 2,
        // solved by Cardano's formula (its one real root).
        const double b = 4 * u - 2, root = std::sqrt(b * b + 1);
        return std::cbrt(b + root) + std::cbrt(b - root);
    }
    case scene::PhaseFunction::HenyeyGreenstein: {
        if (std::abs(g) < 1e-3) break;
        const double s = (1 - g * g) / (1 + g - 2 * g * u);
        return std::clamp((1 + g * g - s * s) / (2 * g), -1.0, 1.0);
    }
    }
    return 1 - 2 * u;
}

} // namespace

Vec3 Medium::samplePhase(const Vec3& d, const Vec2& u) const {
    const double cosTheta = sampleCosine(phase_, g_, u.x);
    const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    const double phi = 2 * kPi * u.y;
    return Frame::fromAxis(glm::normalize(d)).fromLocal({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
}

} // namespace crt::tracer
