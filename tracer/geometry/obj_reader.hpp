// Reading Wavefront OBJ meshes: positions, normals, UVs and fan-triangulated polygons.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace crt::tracer {

/// A triangle mesh as read from a file; indices are 0-based into the vectors, −1 = absent.
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    struct Triangle {
        int32_t v[3];
        int32_t n[3];
        int32_t uv[3];
    };
    std::vector<Triangle> triangles;
};

/// Reads `path`; on failure returns nullopt and sets `error` to "cannot read '<path>'" or
/// to parseObj's message.
std::optional<MeshData> readObj(const std::string& path, std::string& error);

/// Parses OBJ text: `v`, `vn`, `vt` and `f` (polygons fan-triangulated; corners as v, v/vt,
/// v//vn or v/vt/vn; negative indices count back from the latest element). Other statements
/// (o, g, s, usemtl, mtllib, l, …) and `#` comments are ignored; CRLF line ends are fine. On a
/// bad line returns nullopt and sets `error` to "<nameForErrors>:<line>: <message>".
std::optional<MeshData> parseObj(std::string_view text, const std::string& nameForErrors,
                                 std::string& error);

} // namespace crt::tracer
