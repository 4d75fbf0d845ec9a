// The prism primitive: POV-Ray's, an outline of curve segments swept along y.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"
#include "tracer/geometry/outline.hpp"

#include <memory>

namespace crt::tracer {

/// The outline of scene::curveLoops in the x-z plane, swept straight from y = from to y = to,
/// or scaled with y (a conic sweep, the outline being the section at y = 1); a solid when
/// closed by its end faces. UV on the walls: u along the outline (one unit over all its
/// segments, in their order), v from `from` (0) to `to` (1); on the end faces, x and z.
class PrismGeometry {
  public:
    /// An outline that does not close, or heights that coincide, give no crossings at all.
    explicit PrismGeometry(const scene::PrismShape& desc);

    Bounds3 bounds() const { return bounds_; }
    /// Every crossing, ascending; as many as the walls the line meets, plus the end faces.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return !open_; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

  private:
    struct Wall {
        scene::CurveSegment curve;
        Vec2 lo, hi;    ///< the segment's 2D bounds (for the straight sweep's quick miss)
        double outward; ///< +1 when the solid lies left of the curve's direction, else −1
    };
    /// The heavy part, shared by copies.
    struct Shared {
        std::vector<Wall> walls;
        Outline outline;
    };
    /// Calls found(u, t) for each crossing of the line with wall w's surface, heights unchecked.
    template <class Found> void crossWall(const Ray& ray, const Wall& w, const Found& found) const;
    /// The wall point's outward normal at curve parameter u and height y.
    Vec3 wallNormal(const Wall& w, double u, double y) const;

    std::shared_ptr<const Shared> shared_;
    double from_ = 0, to_ = 0;
    bool conic_ = false;
    bool open_ = false;
    Bounds3 bounds_;
};

} // namespace crt::tracer
