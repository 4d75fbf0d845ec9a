// The finite cylinder primitive (capped, or open and then not a solid).
#pragma once

#include "tracer/geometry/axial_solid.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// A cylinder from `base` to `top` around any axis. Crossing::part: 0 side, 1 base cap,
/// 2 top cap. UV: side u = angle around the axis, v = height fraction (0 at base); caps
/// u = angle, v = distance from the axis / radius (see AxialSolid).
class CylinderGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit CylinderGeometry(const scene::CylinderShape& desc);

    /// Object-space bounds, padded against rounding; empty for a degenerate shape.
    Bounds3 bounds() const { return solid_.bounds(); }
    /// Capped: none or two crossings. Open: the side's crossings only.
    void crossLine(const Ray& ray, CrossingList& out) const { solid_.crossLine(ray, out); }
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// An open cylinder has no inside.
    bool solid() const { return solid_.solid(); }
    MappingAxis mappingAxis() const { return solid_.mappingAxis(); }

  private:
    AxialSolid solid_;
};

} // namespace crt::tracer
