// libFuzzer target for the PLY, STL and glTF readers (Assimp): the first byte picks the format,
// the rest is the file.
#include "scene/mesh_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

namespace {

constexpr std::string_view kExtensions[] = {"ply", "stl", "glb", "gltf"};

/// Small, so that the limit's refusal is reached too.
constexpr uint64_t kMaxSize = 4096;

bool validIndex(int32_t index, size_t count, bool optional) {
    if (index == -1) return optional;
    return index >= 0 && static_cast<size_t>(index) < count;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string_view extension = kExtensions[data[0] % std::size(kExtensions)];
    crt::scene::MeshFileError error;
    std::optional<crt::scene::MeshData> mesh =
        crt::scene::parseAssimpMesh(std::span(data + 1, size - 1), extension, kMaxSize, error);
    if (!mesh) {
        if (error.message.empty()) std::abort(); // a rejected file always says why
        return 0;
    }
    // The reader's promise, which the renderer relies on without checking again: triangles,
    // no list longer than the limit, every index in range or absent where that is allowed.
    if (mesh->triangles.empty() || mesh->positions.size() > kMaxSize ||
        mesh->triangles.size() > kMaxSize)
        std::abort();
    for (const crt::scene::MeshData::Triangle& triangle : mesh->triangles) {
        for (int corner = 0; corner < 3; ++corner) {
            if (!validIndex(triangle.v[corner], mesh->positions.size(), false) ||
                !validIndex(triangle.n[corner], mesh->normals.size(), true) ||
                !validIndex(triangle.uv[corner], mesh->uvs.size(), true))
                std::abort();
        }
    }
    return 0;
}
