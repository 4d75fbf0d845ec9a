// The torus primitive: a quartic solved robustly in double precision.
#pragma once

#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// A torus around `axis` through `center`: the points within `minor` of the circle of radius
/// `major`; a closed solid (also when minor > major). UV: u = angle around the axis
/// (counter-clockwise from the frame's u axis, Frame::fromAxis), v = angle around the tube,
/// 0 on the outer equator, rising toward +axis first.
class TorusGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit TorusGeometry(const scene::TorusShape& desc);

    /// Object-space bounds, padded against rounding; empty for a degenerate shape.
    Bounds3 bounds() const;
    /// Zero, two or four crossings, ascending; a tangency gives none or two.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// Usable in CSG: the crossings bound an inside.
    bool solid() const { return true; }
    /// About the centre and the ring's axis.
    MappingAxis mappingAxis() const { return {center_, frame_.w}; }

  private:
    Vec3 center_;
    Frame frame_; ///< w is the axis
    double major_ = 0;
    double minor_ = 0;
    bool empty_ = true;
};

} // namespace crt::tracer
