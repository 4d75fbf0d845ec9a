// The sphere-sweep primitive: POV-Ray's sphere_sweep, a sphere moved along a curve while its
// radius changes.
#pragma once

#include "scene/curve_outline.hpp"
#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// The union of the spheres of centre c(u) and radius r(u) as (c, r) runs along the curve
/// segments of scene::SphereSweepShape.
///
/// Along a line, the u of a segment whose spheres the line meets form runs, over which the
/// points where the line enters and leaves the sphere move continuously; so each run covers
/// one span of the line, from its least entry to its greatest exit. Those lie at the run's
/// ends or where the entry or the exit stops moving: roots of a polynomial in u of degree 2
/// for a straight segment, 10 for a cubic one. The crossings are the ends of the union of
/// all the spans. No UV (as POV-Ray's).
class SphereSweepGeometry {
  public:
    /// Fewer points than the spline needs give no segments, and no crossings.
    explicit SphereSweepGeometry(const scene::SphereSweepShape& desc);

    Bounds3 bounds() const { return bounds_; }
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return true; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

  private:
    /// One piece of the curve: (centre, radius) = ((a·u + b)·u + c)·u + d for u in [0, 1].
    struct Segment {
        scene::CurveSegmentOf<glm::dvec4> curve;
        int degree;  ///< 1 for a straight piece, else 3
        double size; ///< the sum of the coefficients' magnitudes, for rounding bounds
        Bounds3 bounds;
    };
    /// Where the line is inside the spheres of one run of one segment.
    struct Span {
        double t0, t1;
        uint32_t segment;
    };
    /// Appends the spans of segment i the line passes through.
    void crossSegment(const Ray& ray, uint32_t i, std::vector<Span>& spans) const;

    std::shared_ptr<const std::vector<Segment>> segments_;
    Bounds3 bounds_;
};

} // namespace crt::tracer
