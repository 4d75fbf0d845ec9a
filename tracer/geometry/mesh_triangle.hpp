// One triangle of a mesh, with interpolated vertex normals and UVs.
#pragma once

#include "scene/obj_mesh.hpp"
#include "tracer/geometry/triangle.hpp"

#include <memory>

namespace crt::tracer {

using scene::MeshData;

/// Triangle `index` of a mesh; a face of a solid when the mesh is closed (MeshData::closed),
/// else a surface. The vertex positions are copied so the crossing test does not chase the
/// mesh. The geometric normal of a closed mesh's face points out of the solid (the right-hand
/// rule of its corners, or the left-hand one for a mesh wound inward); an open mesh's follows
/// the right-hand rule, turned toward the interpolated vertex normal when the face has them
/// (files disagree on winding, the normals say which side is out). shadingNormal: the vertex
/// normals interpolated (the geometric normal without them); UV: the vertex UVs interpolated,
/// else the barycentric weights of the second and third corners.
class MeshTriangleGeometry {
  public:
    /// An index out of range (or a corner out of range) gives an empty triangle.
    MeshTriangleGeometry(std::shared_ptr<const MeshData> mesh, size_t index);

    /// The vertices' bounds (exact); empty for a degenerate triangle.
    Bounds3 bounds() const { return triangle_.bounds(); }
    /// Every crossing of the whole line, ascending.
    void crossLine(const Ray& ray, CrossingList& out) const { triangle_.crossLine(ray, out); }
    /// The refined point, its error bound, the normal and UV at one of crossLine's crossings.
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    /// A face of a closed mesh's solid.
    bool solid() const { return mesh_ && mesh_->closed; }
    /// For a closed mesh: negative where the line enters the solid, positive where it leaves.
    double facing(const Ray& ray) const {
        return woundInward() ? -triangle_.facing(ray) : triangle_.facing(ray);
    }

  private:
    /// dpdu and dpdv of the face's own uvs (zero when they are degenerate).
    void tangentsFromUvs(const MeshData::Triangle& tri, const Vec2 (&uv)[3],
                         SurfacePoint& sp) const;

    TriangleGeometry triangle_;
    std::shared_ptr<const MeshData> mesh_;
    size_t index_;
    bool hasNormals_ = false;
    bool hasUvs_ = false;

    /// A closed mesh whose outward normals are the left-hand ones: a fact of the mesh, read
    /// from it rather than copied into each triangle.
    bool woundInward() const { return mesh_ && mesh_->closed && mesh_->inward; }
};

} // namespace crt::tracer
