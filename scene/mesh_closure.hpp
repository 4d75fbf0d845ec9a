// Whether a triangle mesh bounds a solid: closed, every edge between two triangles that run
// it in opposite directions. Such a mesh is a CSG operand and glass with an inside.
#pragma once

#include "scene/obj_mesh.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace crt::scene {

/// What meshClosure finds.
struct MeshClosure {
    bool closed = false;
    /// Closed, with its triangles running clockwise seen from outside (a negative volume): its
    /// outward normals are the left-hand ones.
    bool inward = false;
    /// When open: the first edge (by its corners' vertex numbers, from 0) that is not shared
    /// by exactly two triangles running it in opposite directions, and why.
    int32_t edgeFrom = -1, edgeTo = -1;
    std::string problem; ///< "has one triangle", "has 3 triangles", "runs the same way in both"
};

/// For each vertex, the smallest number of a vertex at the same position: files split a
/// vertex where its normals or uvs differ (STL stores three of its own for each triangle).
std::vector<int32_t> firstVertexAtPosition(const std::vector<glm::dvec3>& positions);

/// Corners at the same position count as one vertex (files split vertices where their
/// normals or uvs differ); triangles with two corners at one position have no area and are
/// left out. A mesh without triangles is open.
MeshClosure meshClosure(const MeshData& mesh);

/// Sets the mesh's `closed` and `inward` from meshClosure, and returns it.
MeshClosure markClosure(MeshData& mesh);

} // namespace crt::scene
