// The axis-aligned box primitive (in object space): slab crossings and per-face surface points.
#pragma once

#include "tracer/geometry/shape.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// An axis-aligned box; a closed solid. Crossing::part is the face: 2·axis for the low side,
/// 2·axis + 1 for the high side. UV per face: u along axis (a+1) mod 3, v along (a+2) mod 3,
/// each scaled to [0, 1] over the face.
class BoxGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit BoxGeometry(const scene::BoxShape& desc);

    /// The corners themselves (exact); empty for a zero extent.
    Bounds3 bounds() const;
    /// None or two crossings (entering, leaving); a line in a face plane counts as inside that
    /// slab, so it also gives none or two.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The point snapped exactly onto the crossed face, its error bound, normal and UV.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// Usable in CSG: the crossings bound an inside.
    bool solid() const { return true; }

  private:
    Vec3 lo_;
    Vec3 hi_;
    bool empty_;
};

} // namespace crt::tracer
