// Media: density, coefficients and the three phase functions.
#include "tracer/medium.hpp"

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

} // namespace crt::tracer
