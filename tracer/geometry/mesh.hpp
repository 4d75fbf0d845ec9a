// A triangle mesh as one primitive. Its triangles and a BVH over them are stored once and
// shared by every primitive that draws the mesh, so a mesh drawn a thousand times costs one
// mesh and a thousand small primitives, and a ray is moved into the mesh's space once per
// use rather than once per triangle.
#pragma once

#include "scene/obj_mesh.hpp"
#include "tracer/bvh.hpp"
#include "tracer/geometry/shape.hpp"
#include "tracer/geometry/triangle_quad.hpp"

#include <memory>

namespace crt::tracer {

using scene::MeshData;

/// A mesh's triangles under a BVH of their own, whose leaves are quads of up to four
/// triangles in float (triangle_quad.hpp). Triangles with a corner out of range or not
/// finite, and those of no area, are left out of the BVH: no line crosses them. Its nodes
/// have eight children: the tree is about half as deep as with four, and its search is most
/// of a mesh's render.
class TriangleMesh {
  public:
    explicit TriangleMesh(std::shared_ptr<const MeshData> data, unsigned threads = 1);

    const MeshData& data() const { return *data_; }
    /// Its items are quads.
    const WideBvh<8>& bvh() const { return bvh_; }
    const TriangleQuad& quad(int32_t i) const { return quads_[static_cast<size_t>(i)]; }
    /// The frame the quads' corners are in.
    const QuadFrame& frame() const { return frame_; }
    /// Of the triangles in the BVH; empty when there are none.
    const Bounds3& bounds() const { return bounds_; }
    /// The corners of triangle i (one the BVH holds).
    void corners(uint32_t i, Vec3 (&p)[3]) const {
        const MeshData::Triangle& tri = data_->triangles[i];
        for (int k = 0; k < 3; ++k) p[k] = data_->positions[static_cast<size_t>(tri.v[k])];
    }
    /// The bytes the mesh and its BVH hold.
    uint64_t byteSize() const {
        return sizeof(TriangleMesh) + data_->byteSize() + bvh_.byteSize() + quads_.capacity() * sizeof(TriangleQuad);
    }

  private:
    std::shared_ptr<const MeshData> data_;
    WideBvh<8> bvh_;
    Bounds3 bounds_;
    QuadFrame frame_;
    std::vector<TriangleQuad> quads_;
};

/// A mesh drawn as one primitive; each crossing's part is the index of the triangle crossed.
/// A closed mesh (MeshData::closed) is a solid whose faces' geometric normals point out of it
/// (the right-hand rule of their corners, or the left-hand one for a mesh wound inward); an
/// open mesh is a surface whose faces follow the right-hand rule, turned toward the
/// interpolated vertex normal where the face has them (files disagree on winding, the normals
/// say which side is out). shadingNormal: the vertex normals interpolated (the geometric
/// normal without them); UV: the vertex UVs interpolated, else the barycentric weights of the
/// second and third corners.
class MeshGeometry {
  public:
    explicit MeshGeometry(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)) {}

    Bounds3 bounds() const { return mesh_->bounds(); }
    /// Every crossing of the whole line, ascending. Of a closed mesh only those that alternate
    /// between entering and leaving: a line through an edge or a vertex meets the triangles
    /// around it more than once there.
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// The crossings with tMin < t < tMax, each triangle's but `skippedPart`'s (the face a ray
    /// leaves from; kNoPart for none), in the order the BVH's search meets them, until visit
    /// returns false: a visitor that stops early spares the search of the rest.
    bool crossingsIn(const Ray& ray, double tMin, double tMax, CrossingVisitor visit, uint32_t skippedPart) const;
    /// The nearest crossing with tMin < t < tMax, not testing triangle `skippedPart`.
    bool firstCrossingIn(const Ray& ray, double tMin, double tMax, Crossing& out,
                         uint32_t skippedPart) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return mesh_->data().closed; }

    const TriangleMesh& mesh() const { return *mesh_; }

  private:
    /// dpdu and dpdv of the face's own uvs (zero when they are degenerate).
    void tangentsFromUvs(const MeshData::Triangle& tri, const Vec2 (&uv)[3], SurfacePoint& sp) const;

    std::shared_ptr<const TriangleMesh> mesh_;
};

} // namespace crt::tracer
