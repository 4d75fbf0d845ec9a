// The surface of revolution primitive: POV-Ray's sor, a radius given by cubics of the height.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// The solid where x² + z² ≤ R(y) between the heights of the second point and the last
/// but one, R being piecewise cubic (scene::SorShape); closed by flat end faces unless open.
/// UV as POV-Ray's: u = angle around y, atan2(z, x) / 2π; v on the side from 0 at the bottom
/// to 1 at the top, in equal steps per segment; on the bottom face from −1 (centre) to 0
/// (rim), on the top face from 2 (centre) to 1 (rim).
class SorGeometry {
  public:
    /// Fewer than four points, or heights that do not rise, give no crossings at all.
    explicit SorGeometry(const scene::SorShape& desc);

    Bounds3 bounds() const { return bounds_; }
    /// Every crossing, ascending: the side where x² + z² − R(y) changes sign, and the faces.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return !open_; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

  private:
    /// R between heights y0 and y1 as a cubic of s = (y − y0) / (y1 − y0): the Hermite cubic
    /// with values k0, k1 (the radii squared) and slopes in s.
    struct Segment {
        double y0, y1;
        double k0, k1;
        double c3, c2, c1; ///< R(s) = ((c3·s + c2)·s + c1)·s + k0
        double at(double s) const { return ((c3 * s + c2) * s + c1) * s + k0; }
        double slope(double s) const { return (3 * c3 * s + 2 * c2) * s + c1; }
    };
    /// Appends the side's crossings within segment i, for a line not level.
    void crossSegment(const Ray& ray, size_t i, CrossingList& out) const;

    std::shared_ptr<const std::vector<Segment>> segments_;
    bool open_ = false;
    Bounds3 bounds_;
};

} // namespace crt::tracer
