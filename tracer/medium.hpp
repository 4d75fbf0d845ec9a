// A medium that fills a solid (spec §5, Medium), as shading reads it: its coefficients at a
// point, scaled by its density there, and how it scatters.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "tracer/texture.hpp"
#include "scene/scene_desc.hpp"

#include <cmath>
#include <optional>

namespace crt::tracer {

/// The longest stretch of a medium a ray is followed through: what a ray that leaves no solid
/// (inside an unbounded one) crosses.
inline constexpr double kLongestMediumStretch = 1e6;

/// What a stretch of `length` lets through, exp(−σ·length), per channel.
inline Vec3 transmittanceOver(const Vec3& sigma, double length) {
    return {std::exp(-sigma.x * length), std::exp(-sigma.y * length), std::exp(-sigma.z * length)};
}

/// ∫₀^length exp(−σ·s) ds per channel (σ may be negative or 0): what a source of unit
/// strength along the stretch sends to its start.
inline Vec3 integratedTransmittance(const Vec3& sigma, double length) {
    Vec3 w;
    for (int c = 0; c < 3; ++c) w[c] = sigma[c] != 0 ? -std::expm1(-sigma[c] * length) / sigma[c] : length;
    return w;
}

class Medium {
public:
    explicit Medium(const scene::MediumDesc& desc);

    /// The density at a world point: the pattern's value there (clamped to [0, 1]) times
    /// `density`, or `density` everywhere.
    double density(const Vec3& p) const;
    bool homogeneous() const { return !pattern_; }
    /// Per unit length at density 1.
    const Vec3& absorption() const { return absorption_; }
    const Vec3& scattering() const { return scattering_; }
    const Vec3& emission() const { return emission_; }
    Vec3 extinction() const { return absorption_ + scattering_; }
    /// The phase function's density at cos θ, θ the angle between the direction light
    /// travelled and the direction it is scattered into (it integrates to 1 over the sphere).
    double phase(double cosTheta) const;
    /// A direction drawn by the phase function from `u` in [0, 1)²: the way light comes from
    /// that scatters along −d, so its density is phase(wi · d) (a path arriving along d goes
    /// on along wi).
    Vec3 samplePhase(const Vec3& d, const Vec2& u) const;
    int samples() const { return samples_; }
    /// The most density() may be anywhere.
    double densityBound() const { return density_; }

private:
    Vec3 absorption_, scattering_, emission_;
    double density_;
    std::optional<Texture> pattern_;
    scene::PhaseFunction phase_;
    double g_;
    int samples_;
};

} // namespace crt::tracer
