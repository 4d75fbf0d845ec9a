// A mesh, or why there is none, as bytes and back: how a mesh read in a child process
// (child_process.hpp) comes back to the parent.
#pragma once

#include "scene/mesh_file.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace crt::scene {

/// The mesh, or the error when there is none.
std::string meshToBytes(const std::optional<MeshData>& mesh, const MeshFileError& error);

/// The most bytes meshToBytes makes of a mesh within the limit of `maxSize` vertices and
/// triangles (and of any error).
uint64_t meshBytesBound(uint64_t maxSize);

/// meshToBytes undone; bytes cut short or otherwise not from it give nullopt and an error
/// saying so.
std::optional<MeshData> meshFromBytes(std::string_view bytes, MeshFileError& error);

} // namespace crt::scene
