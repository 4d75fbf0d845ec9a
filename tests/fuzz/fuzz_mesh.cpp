// libFuzzer target for the PLY, STL and glTF readers (Assimp): the first byte picks the format,
// the rest is the file.
#include "mesh_promise.hpp"

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
    if (mesh->triangles.empty() || !crt::fuzz::keepsMeshPromise(*mesh, kMaxSize)) std::abort();
    return 0;
}
