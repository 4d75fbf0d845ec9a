// The sphere primitive: exact line crossings and refined surface points.
#pragma once

#include "tracer/geometry/area_sample.hpp"
#include "tracer/geometry/mapping_axis.hpp"
#include "tracer/geometry/shape.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// A sphere; a closed solid. UV: u = longitude atan2(z, x) / 2π around +y (from +x toward +z),
/// v = latitude, 0 at the −y pole and 1 at the +y pole.
class SphereGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit SphereGeometry(const scene::SphereShape& desc);

    /// Object-space bounds (empty for a zero radius).
    Bounds3 bounds() const;
    /// Every crossing of the whole line, ascending: none or two (a tangent line gives two equal).
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The crossing's point reprojected onto the sphere, its error bound, outward normal and UV.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// Usable in CSG: the crossings bound an inside.
    bool solid() const { return true; }
    const Vec3& center() const { return center_; }
    double radius() const { return radius_; }
    /// Its area, and a point of it uniform by area for u uniform in [0, 1)².
    double area() const;
    AreaSample sampleArea(const Vec2& u) const;
    /// About the centre, +y up.
    MappingAxis mappingAxis() const { return {center_, Vec3(0, 1, 0)}; }

  private:
    Vec3 center_;
    double radius_;
};

} // namespace crt::tracer
