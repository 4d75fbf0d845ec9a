// The quad primitive: a bounded parallelogram; a surface, not a solid.
#pragma once

#include "tracer/geometry/area_sample.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// The points corner + α·edgeA + β·edgeB with α, β in [0, 1]. Normal: edgeA × edgeB,
/// normalised (right-hand rule). UV: (α, β).
class QuadGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit QuadGeometry(const scene::QuadShape& desc);

    /// Object-space bounds, padded against rounding; empty for a degenerate shape.
    Bounds3 bounds() const;
    /// None or one crossing; none for a line parallel to the quad.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// A surface without an inside: not usable in CSG.
    bool solid() const { return false; }

    /// Its area, and a point of it uniform by area for u uniform in [0, 1)².
    double area() const;
    AreaSample sampleArea(const Vec2& u) const;

  private:
    Vec3 corner_;
    Vec3 edgeA_;
    Vec3 edgeB_;
    Vec3 normal_{0, 1, 0};
    Vec3 toAlpha_{0.0}; ///< α = toAlpha·(p − corner) for p in the plane
    Vec3 toBeta_{0.0};  ///< β = toBeta·(p − corner)
    Vec3 tilt_{0.0};    ///< per-component bound of the unit normal's error (but its length)
    bool empty_ = true;
};

} // namespace crt::tracer
