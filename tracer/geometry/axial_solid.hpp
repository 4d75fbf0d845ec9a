// The capped solid of revolution behind both the cylinder and the cone primitives.
#pragma once

#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

namespace crt::tracer {

/// A frustum around an arbitrary axis: in a local frame at `base`, the points with
/// 0 ≤ z ≤ height and x² + y² ≤ (r0 + slope·z)². Crossing::part: 0 the side, 1 the base cap,
/// 2 the top cap. UV: side u = angle around the axis, v = z / height; caps u = angle,
/// v = distance from the axis / the cap's radius. Angles are counter-clockwise from the
/// frame's u axis (Frame::fromAxis of the axis direction).
class AxialSolid {
  public:
    AxialSolid(const Vec3& base, const Vec3& top, double baseRadius, double topRadius, bool open);

    /// Object-space bounds, padded against rounding; empty for a degenerate shape.
    Bounds3 bounds() const;
    /// Closed: none or two crossings (a tangent line gives two equal ones). Open: only the
    /// side's crossings within the height, zero to two.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return !open_; }
    /// From the base, along the axis.
    MappingAxis mappingAxis() const { return {base_, frame_.w}; }

  private:
    Vec3 base_;
    Frame frame_;
    double height_ = 0;
    double r0_ = 0;    ///< radius at the base
    double r1_ = 0;    ///< radius at the top
    double slope_ = 0; ///< (r1 − r0) / height
    bool open_ = false;
    bool empty_ = true;
};

} // namespace crt::tracer
