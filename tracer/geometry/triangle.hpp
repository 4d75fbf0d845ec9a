// The triangle primitive: watertight line crossing in double; a surface, not a solid.
#pragma once

#include "tracer/geometry/area_sample.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// The watertight line-triangle test (Woop et al.) on corners p: the line's parameter t and
/// the barycentric weights of the three corners, or false. A line through a shared edge or
/// vertex of a mesh crosses at least one of the triangles around it; a line parallel to the
/// triangle, or a degenerate triangle, crosses nothing.
bool crossTriangle(const Vec3 (&p)[3], const Ray& ray, double& t, Vec3& weights);

/// The triangle (a, b, c). Normal: (b − a) × (c − a), normalised (right-hand rule).
/// UV: the barycentric weights of b and c.
class TriangleGeometry {
  public:
    /// A degenerate desc (zero radius or extent, zero normal) gives no crossings at all.
    explicit TriangleGeometry(const scene::TriangleShape& desc);

    /// The vertices' bounds (exact); empty for a degenerate triangle.
    Bounds3 bounds() const;
    /// None or one crossing. Watertight (Woop et al.): a line through a shared edge or vertex
    /// of a mesh hits at least one of the triangles around it; none for a parallel line.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The refined point, its error bound, the normal and (with wantUv) the UV at one of
    /// crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// A surface without an inside: not usable in CSG.
    bool solid() const { return false; }

    /// n · d for the line's direction d and the normal above: negative where the line meets
    /// the face from the side the normal points to.
    double facing(const Ray& ray) const { return glm::dot(normal_, ray.dir); }
    /// The barycentric weights of a, b and c at a crossing (for interpolating vertex data).
    Vec3 barycentrics(const Ray& ray, const Crossing& crossing) const;

    /// Its area, and a point of it uniform by area for u uniform in [0, 1)².
    double area() const;
    AreaSample sampleArea(const Vec2& u) const;

  private:
    /// The watertight test: the line's parameter and the barycentric weights, or false.
    bool intersect(const Ray& ray, double& t, Vec3& weights) const;

    Vec3 p_[3];
    Vec3 normal_{0, 1, 0};
    Vec3 tilt_{0.0}; ///< per-component bound of the unit normal's error (but its length)
    bool empty_ = true;
};

} // namespace crt::tracer
