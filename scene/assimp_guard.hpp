// The checks a mesh file must pass before Assimp reads it. Assimp reserves room for the sizes
// a file declares before it reads the data they describe (2 billion PLY vertices, a GLB chunk
// of a gigabyte), and loops forever on some malformed PLY headers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace crt::scene {

/// Reads `size` bytes at `offset` of a file into `to`; false when the file has fewer.
using ByteReader = std::function<bool(uint64_t offset, void* to, size_t size)>;

/// Why a file of this extension ("ply", "stl", "glb", "gltf") and size is refused before
/// Assimp reads it ("" when it is not): plyHeaderProblem or glbProblem.
std::string assimpGuardProblem(std::string_view extension, const ByteReader& read,
                               uint64_t fileSize);

/// Why a PLY file is refused before Assimp reads it ("" when it is not), from its first bytes
/// (the header must fit in 64 KiB) and its size. The header must be plain PLY, line by line (the
/// keywords, known types, whole numbers), and each element must fit in the data: at least
/// its properties' bytes (binary; a list at least its count) or two characters a property
/// (text: a digit and a space).
std::string plyHeaderProblem(std::string_view head, uint64_t fileSize);

/// Why a GLB file (binary glTF) is refused before Assimp reads it ("" when it is not): its
/// header must be a GLB 2 header whose length is the file's, and its chunks must lie inside
/// that length.
std::string glbProblem(const ByteReader& read, uint64_t fileSize);

} // namespace crt::scene
