// A panorama background as a light the path integrator aims at: directions drawn by the
// panorama's luminance, so a small sun in a wide sky is found without noise.
#pragma once

#include "tracer/background.hpp"
#include "tracer/distribution.hpp"

#include <optional>

namespace crt::tracer {

class EnvironmentLight {
public:
    /// Samples the background when it is a panorama; otherwise inactive (a colour or a
    /// gradient is smooth, and the BSDF's own directions find it well).
    explicit EnvironmentLight(const Background& background);

    bool active() const { return distribution_.has_value(); }
    /// A unit direction and its density in solid angle (0 when none could be had).
    Vec3 sample(const Vec2& u, double& pdf) const;
    /// The density sample() has of direction d.
    double pdf(const Vec3& d) const;

    /// The grid the distribution is built on is at most this many cells wide (and half as
    /// high): finer than the bright features that matter, coarser than large panoramas.
    static constexpr int kMaxColumns = 512;

private:
    const Background& background_;
    std::optional<Distribution2D> distribution_;
};

} // namespace crt::tracer
