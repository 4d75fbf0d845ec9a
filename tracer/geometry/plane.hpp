// The infinite plane primitive; as a solid, the half-space behind its normal.
#pragma once

#include "tracer/geometry/geometry_math.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// A plane through `position` with unit normal n; the solid is {p : n·(p − position) ≤ 0}.
/// UV: the point's coordinates along two fixed orthonormal directions in the plane, measured
/// from `position` (not wrapped, so textures tile by their own rules).
class PlaneGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit PlaneGeometry(const scene::PlaneShape& desc);

    /// Everything: a plane is unbounded (it lives outside the BVH).
    Bounds3 bounds() const { return Bounds3::everything(); }
    /// At most one crossing; startsInside tells whether the line begins behind the plane
    /// (a line parallel to the plane has no crossing and is wholly inside or outside).
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The point projected onto the plane, its error bound, the normal n and UV.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// Usable in CSG: the crossings bound an inside.
    bool solid() const { return true; }

    /// The unit normal and a point of the plane (for the renderer's plane fast path).
    const Vec3& normal() const { return frame_.w; }
    const Vec3& position() const { return position_; }
    bool empty() const { return empty_; }

  private:
    Vec3 position_;
    Frame frame_; ///< w is the unit normal
    bool empty_;  ///< a zero normal: no plane at all
};

} // namespace crt::tracer
