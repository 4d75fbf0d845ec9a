// The lathe primitive: POV-Ray's, a curve in the x-y plane turned about the y axis.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// The surface swept by the curve of scene::curveSegments, x being the distance from the y
/// axis, turned about that axis. A solid when the curve closes (or runs from the axis to the
/// axis), its normals then pointing out of the region it bounds; else a surface. UV as
/// POV-Ray's: u = angle around y, atan2(z, x) / 2π; v along the curve from 0 to 1, in equal
/// steps per segment.
class LatheGeometry {
  public:
    /// A curve without segments gives no crossings at all.
    explicit LatheGeometry(const scene::LatheShape& desc);

    Bounds3 bounds() const { return bounds_; }
    /// Every crossing, ascending: where the line's distance from the axis passes the curve's.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return solid_; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

  private:
    struct Segment {
        scene::CurveSegment curve;
        double yLo, yHi, radius; ///< the heights and the largest distance from the axis
    };
    /// Appends the crossings with segment i, for a line not level (its y changes).
    void crossSegment(const Ray& ray, uint32_t i, CrossingList& out) const;
    /// Appends the crossings with every segment, for a level line.
    void crossLevel(const Ray& ray, CrossingList& out) const;
    /// The curve parameter of segment i nearest to the point (rho, y) of the x-y plane.
    double nearestParameter(const Segment& seg, Vec2 point) const;

    std::shared_ptr<const std::vector<Segment>> segments_;
    double outward_ = 1; ///< +1 when the region lies left of the curve's direction, else −1
    bool solid_ = false;
    Bounds3 bounds_;
};

} // namespace crt::tracer
