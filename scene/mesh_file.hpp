// Mesh files of every format crt reads: Wavefront OBJ by its own reader (obj_mesh.hpp), which
// points at the bad line; PLY, STL and glTF 2.0 (.gltf, .glb) through Assimp.
#pragma once

#include "scene/obj_mesh.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace crt::scene {

/// Why a file other than the mesh itself (a glTF's buffer) may not be read: "" when it may.
using FileGate = std::function<std::string(const std::string& path)>;

/// Whether the file's name (its extension, in any case) makes it a PLY, STL or glTF file,
/// read by readAssimpMesh; any other mesh file is read as OBJ.
bool isAssimpMeshFile(std::string_view path);

/// Why a PLY, STL or glTF file is not a usable mesh.
struct MeshFileError {
    std::string message;
    bool overLimit = false; ///< the mesh is larger than the limit allows
};

/// Reads a PLY, STL or glTF file as one mesh, in a child process (Assimp's faults stay there,
/// an error here): the triangles of every mesh in its scene, each
/// placed by its node's transforms (polygons fan-triangulated, points and lines left out);
/// vertex normals and the first set of texture coordinates where the file has them (a glTF's
/// v turned to OBJ's, upward). Files the mesh refers to are read only where `gate` allows. An
/// unreadable or damaged file, one without triangles, or more than `maxSize` vertices or
/// triangles give nullopt and `error`.
std::optional<MeshData> readAssimpMesh(const std::string& path, uint64_t maxSize,
                                       const FileGate& gate, MeshFileError& error);

/// The same from the bytes of a file whose extension is `extension` ("ply", "stl", "glb" or
/// "gltf"), in this process (for fuzzing Assimp's readers); it can refer to no other file.
std::optional<MeshData> parseAssimpMesh(std::span<const uint8_t> bytes, std::string_view extension,
                                        uint64_t maxSize, MeshFileError& error);

/// Reads a mesh file of any of the formats above; on failure `error` is a whole message
/// naming the file. Files it refers to are read only where `gate` allows (all when empty).
std::optional<MeshData> readMeshFile(const std::string& path, uint64_t maxSize, std::string& error,
                                     const FileGate& gate = {});

} // namespace crt::scene
