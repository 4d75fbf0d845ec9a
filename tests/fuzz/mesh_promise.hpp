// What every mesh reader promises of the mesh it gives, which the renderer relies on without
// checking again: every index refers to an element read, or is absent (−1) where that is
// allowed, and no list is longer than the limit. Shared by the mesh readers' fuzz targets.
#pragma once

#include "scene/obj_mesh.hpp"

#include <cstddef>
#include <cstdint>

namespace crt::fuzz {

inline bool validIndex(int32_t index, size_t count, bool optional) {
    if (index == -1) return optional;
    return index >= 0 && static_cast<size_t>(index) < count;
}

inline bool keepsMeshPromise(const scene::MeshData& mesh, uint64_t maxSize) {
    if (mesh.positions.size() > maxSize || mesh.normals.size() > maxSize ||
        mesh.uvs.size() > maxSize || mesh.triangles.size() > maxSize)
        return false;
    for (const scene::MeshData::Triangle& triangle : mesh.triangles) {
        for (int corner = 0; corner < 3; ++corner) {
            if (!validIndex(triangle.v[corner], mesh.positions.size(), false) ||
                !validIndex(triangle.n[corner], mesh.normals.size(), true) ||
                !validIndex(triangle.uv[corner], mesh.uvs.size(), true))
                return false;
        }
    }
    return true;
}

} // namespace crt::fuzz
