// Wavefront OBJ meshes: positions, normals, UVs and fan-triangulated polygons.
//
// Part of the scene description because both sides need it: the front end reads a script's
// meshes so that a bad file is an error of the script (with the file's line as a note), and
// the renderer draws the data it read.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace crt::scene {

/// A triangle mesh as read from a file; indices are 0-based into the vectors, −1 = absent.
struct MeshData {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec2> uvs;
    struct Triangle {
        int32_t v[3];
        int32_t n[3];
        int32_t uv[3];
    };
    std::vector<Triangle> triangles;
    /// Whether the triangles bound a solid, and whether they run clockwise seen from outside
    /// (scene/mesh_closure.hpp's markClosure sets both).
    bool closed = false;
    bool inward = false;

    /// The bytes the mesh holds (for memory budgets).
    uint64_t byteSize() const;
};

/// The most vertices, normals, texture coordinates or triangles (each counted on its own) one
/// mesh file may hold unless a limit says otherwise (crtc's --max-mesh-size).
inline constexpr uint64_t kDefaultMaxMeshSize = 10'000'000;

/// Why a text is not a usable mesh, and where.
struct ObjError {
    std::string message;
    uint32_t line = 0;      ///< 1-based line of the problem; 0 when it is about the whole file
    size_t begin = 0;       ///< the bytes of the text the message is about (with line != 0)
    size_t end = 0;
    bool overLimit = false; ///< the mesh is larger than the limit allows

    /// "<name>:<line>: <message>", or "<name>: <message>" for the whole file.
    std::string describe(const std::string& name) const;
};

/// Parses OBJ text: `v`, `vn`, `vt` and `f` (polygons fan-triangulated; corners as v, v/vt,
/// v//vn or v/vt/vn; negative indices count back from the latest element). Other statements
/// (o, g, s, usemtl, mtllib, l, …) and `#` comments are ignored; CRLF line ends are fine. A
/// binary file, a text without any OBJ statement, a bad line, or more than `maxSize` elements
/// of one kind give nullopt and `error`.
std::optional<MeshData> parseObj(std::string_view text, uint64_t maxSize, ObjError& error);

/// Reads and parses the file at `path`; on failure `error` is a whole message naming the file
/// (ObjError::describe, or "cannot read '<path>'").
std::optional<MeshData> readObj(const std::string& path, uint64_t maxSize, std::string& error);

} // namespace crt::scene
