// libFuzzer target for the Wavefront OBJ reader: arbitrary bytes as an OBJ file's text.
#include "scene/obj_mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

/// Whether `index` is absent (−1) or refers to one of `count` elements.
bool validIndex(int32_t index, size_t count, bool optional) {
    if (index == -1) return optional;
    return index >= 0 && static_cast<size_t>(index) < count;
}

/// Small, so that the limit's refusal is reached too.
constexpr uint64_t kMaxSize = 4096;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    crt::scene::ObjError error;
    std::optional<crt::scene::MeshData> mesh = crt::scene::parseObj(text, kMaxSize, error);
    if (!mesh) {
        // A rejected file always says why; a line's problem points at bytes of that line.
        if (error.message.empty() || error.begin > error.end || error.end > size) std::abort();
        if (error.line != 0 && text.substr(error.begin, error.end - error.begin).find('\n') !=
                                   std::string_view::npos)
            std::abort();
        return 0;
    }
    // The reader's promise: every index refers to an element read, or is absent (−1) where
    // that is allowed; no list is longer than the limit. The renderer relies on it without
    // checking again.
    if (mesh->positions.size() > kMaxSize || mesh->normals.size() > kMaxSize ||
        mesh->uvs.size() > kMaxSize || mesh->triangles.size() > kMaxSize)
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
