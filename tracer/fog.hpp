// Fog (spec §5, Fog): light lost and fog colour gained along a ray outside every solid.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// What a stretch of fog does to the light that crosses it: what is seen through it is
/// `behind` × transmittance + inscattered.
struct FogCrossing {
    Vec3 transmittance{1.0};
    Vec3 inscattered{0.0};

    Vec3 seen(const Vec3& behind) const { return inscattered + transmittance * behind; }
};

class Fog {
public:
    explicit Fog(const scene::FogDesc& desc);

    /// The fog between ray.origin and `distance` along ray.dir (unit); kInfinity for a ray
    /// that meets nothing.
    FogCrossing along(const Ray& ray, double distance) const;

private:
    /// The mean density between heights (above the altitude, in units of the falloff) a and b.
    static double meanGroundDensity(double a, double b);

    scene::FogDesc desc_;
    Vec3 color_;
    double leastSeen_; ///< what the colour's alpha always lets through
};

} // namespace crt::tracer
