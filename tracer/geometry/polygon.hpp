// The polygon primitive: POV-Ray's, loops with holes in one plane; a surface, not a solid.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/outline.hpp"

#include <memory>

namespace crt::tracer {

/// The points of scene::polygonLoops, read by the even-odd rule in the plane of the first
/// loop. Normal: that loop's right-hand rule. UV: distances from the first point along two
/// fixed directions of the plane (not wrapped), as on a Plane.
class PolygonGeometry {
  public:
    /// Fewer than three points, or a first loop with no area, give no crossings at all.
    explicit PolygonGeometry(const scene::PolygonShape& desc);

    Bounds3 bounds() const { return bounds_; }
    /// None or one crossing.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return false; }

  private:
    /// The plane's point in the 2D coordinates of the outline (the normal's largest axis dropped).
    Vec2 project(const Vec3& p) const;

    std::shared_ptr<const Outline> outline_; ///< shared: the points are the heavy part
    Vec3 origin_{0.0};                       ///< the first point
    Vec3 normal_{0, 1, 0};
    Vec3 tilt_{0.0}; ///< per-component bound of the unit normal's error (but its length)
    Bounds3 bounds_;
    int dropped_ = 1;
};

} // namespace crt::tracer
