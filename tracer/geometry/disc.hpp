// The disc primitive (with an optional hole: an annulus); a surface, not a solid.
#pragma once

#include "tracer/geometry/area_sample.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// The points of the plane through `center` (normal n) at a distance in [hole, radius] from
/// it. The normal is the desc's, normalised. UV: u = angle around n, counter-clockwise from
/// the frame's u axis (Frame::fromAxis(n)), v = distance from the centre / radius.
class DiscGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit DiscGeometry(const scene::DiscShape& desc);

    /// Object-space bounds, padded against rounding; empty for a degenerate shape.
    Bounds3 bounds() const;
    /// None or one crossing; none for a line parallel to the disc.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// A surface without an inside: not usable in CSG.
    bool solid() const { return false; }

    /// Its area, and a point of it uniform by area for u uniform in [0, 1)².
    double area() const;
    AreaSample sampleArea(const Vec2& u) const;

  private:
    Vec3 center_;
    Frame frame_; ///< w is the normal
    double radius_ = 0;
    double hole_ = 0;
    bool empty_ = true;
};

} // namespace crt::tracer
