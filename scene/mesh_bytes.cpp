// A mesh, or why there is none, as bytes and back (see mesh_bytes.hpp).
#include "scene/mesh_bytes.hpp"

#include <cstring>
#include <type_traits>

namespace crt::scene {

namespace {

template <typename T> void put(std::string& out, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T> void putAll(std::string& out, const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(out, uint64_t(values.size()));
    if (!values.empty()) // an empty vector's data() may be null
        out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// What putAll writes for `values`.
template <typename T> size_t bytesOf(const std::vector<T>& values) {
    return sizeof(uint64_t) + values.size() * sizeof(T);
}

/// Reads values in order from the bytes, failing once they run out.
struct Reader {
    std::string_view bytes;
    bool ok = true;

    template <typename T> T get() {
        T value{};
        if (bytes.size() < sizeof(T)) {
            ok = false;
            return value;
        }
        std::memcpy(&value, bytes.data(), sizeof(T));
        bytes.remove_prefix(sizeof(T));
        return value;
    }
    template <typename T> void getAll(std::vector<T>& values) {
        const auto count = get<uint64_t>();
        if (!ok || count > bytes.size() / sizeof(T)) {
            ok = false;
            return;
        }
        values.resize(count);
        if (count > 0) std::memcpy(values.data(), bytes.data(), count * sizeof(T));
        bytes.remove_prefix(count * sizeof(T));
    }
};

} // namespace

std::string meshToBytes(const std::optional<MeshData>& mesh, const MeshFileError& error) {
    std::string out;
    put(out, uint8_t(mesh.has_value()));
    if (!mesh) {
        put(out, uint8_t(error.overLimit));
        out += error.message;
        return out;
    }
    // Room for it all at once: a string grown by doubling would copy hundreds of megabytes
    // for a large mesh.
    out.reserve(out.size() + bytesOf(mesh->positions) + bytesOf(mesh->normals) +
                bytesOf(mesh->uvs) + bytesOf(mesh->triangles) + 2 * sizeof(uint8_t));
    putAll(out, mesh->positions);
    putAll(out, mesh->normals);
    putAll(out, mesh->uvs);
    putAll(out, mesh->triangles);
    put(out, uint8_t(mesh->closed));
    put(out, uint8_t(mesh->inward));
    return out;
}

uint64_t meshBytesBound(uint64_t maxSize) {
    const uint64_t perVertex = 2 * sizeof(glm::dvec3) + sizeof(glm::dvec2);
    const uint64_t bound = maxSize * (perVertex + sizeof(MeshData::Triangle));
    const uint64_t slack = 1 << 20; // the counts, the flags, an error message
    return bound / (perVertex + sizeof(MeshData::Triangle)) == maxSize ? bound + slack : UINT64_MAX;
}

std::optional<MeshData> meshFromBytes(std::string_view bytes, MeshFileError& error) {
    Reader in{bytes};
    const bool has = in.get<uint8_t>() != 0;
    if (in.ok && !has) {
        error.overLimit = in.get<uint8_t>() != 0;
        error.message = std::string(in.bytes);
        if (in.ok && !error.message.empty()) return std::nullopt;
    }
    MeshData mesh;
    in.getAll(mesh.positions);
    in.getAll(mesh.normals);
    in.getAll(mesh.uvs);
    in.getAll(mesh.triangles);
    mesh.closed = in.get<uint8_t>() != 0;
    mesh.inward = in.get<uint8_t>() != 0;
    if (!in.ok || !has || !in.bytes.empty()) {
        error = {"the reader's answer was cut short"};
        return std::nullopt;
    }
    return mesh;
}

} // namespace crt::scene
