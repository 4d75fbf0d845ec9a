// libFuzzer target for the Wavefront OBJ reader: arbitrary bytes as an OBJ file's text.
#include "tracer/geometry/obj_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

/// Whether `index` is absent (−1) or refers to one of `count` elements.
bool validIndex(int32_t index, size_t count, bool optional) {
    if (index == -1) return optional;
    return index >= 0 && static_cast<size_t>(index) < count;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::string error;
    std::optional<crt::tracer::MeshData> mesh = crt::tracer::parseObj(text, "fuzz.obj", error);
    if (!mesh) {
        // A rejected file always says why, and where.
        if (error.rfind("fuzz.obj:", 0) != 0) std::abort();
        return 0;
    }
    // The reader's promise: every index refers to an element read, or is absent (−1) where
    // that is allowed. The mesh builder relies on it without checking again.
    for (const crt::tracer::MeshData::Triangle& triangle : mesh->triangles) {
        for (int corner = 0; corner < 3; ++corner) {
            if (!validIndex(triangle.v[corner], mesh->positions.size(), false) ||
                !validIndex(triangle.n[corner], mesh->normals.size(), true) ||
                !validIndex(triangle.uv[corner], mesh->uvs.size(), true))
                std::abort();
        }
    }
    return 0;
}
