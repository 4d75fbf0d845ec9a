// The header of a PLY file, checked before Assimp reads the file: Assimp reserves room for the
// counts a header declares before it reads any data, and loops forever on some malformed
// headers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace crt::scene {

/// How much of a PLY file's start its header must fit in.
inline constexpr size_t kPlyHeadBytes = 64 * 1024;

/// Why a PLY file is refused before Assimp reads it ("" when it is not), from its first bytes
/// (up to kPlyHeadBytes) and its size. The header must be plain PLY, line by line (the
/// keywords, known types, whole numbers), and each element must fit in the data: at least
/// its properties' bytes (binary; a list at least its count) or two characters a property
/// (text: a digit and a space).
std::string plyHeaderProblem(std::string_view head, uint64_t fileSize);

} // namespace crt::scene
