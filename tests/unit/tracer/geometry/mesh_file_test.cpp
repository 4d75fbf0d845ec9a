// PLY, STL and glTF meshes through Assimp: the same tetrahedron in each format reads as the
// same triangles; normals, UVs and node transforms; a glTF's buffer behind the file gate;
// damaged files, headers that declare more than the file holds, and the size limit.
#include "geometry_test_support.hpp"

#include "scene/mesh_file.hpp"

#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <vector>

using namespace crt::tracer;
namespace fs = std::filesystem;
using crt::scene::kDefaultMaxMeshSize;
using crt::scene::MeshFileError;

namespace {

/// A folder of its own for each test, removed after it.
struct TempFolder {
    fs::path path;
    explicit TempFolder(const std::string& name)
        : path(fs::temp_directory_path() / ("crt_mesh_file_test_" + name)) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
    std::string write(const std::string& name, const std::string& bytes) const {
        std::ofstream(path / name, std::ios::binary) << bytes;
        return (path / name).string();
    }
};

/// Little-endian bytes of numbers, for binary PLY, STL and glTF buffers.
struct Bytes {
    std::string data;
    template <typename T> Bytes& put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        data.append(raw, sizeof(T));
        return *this;
    }
};

// A tetrahedron with outward faces: corners and the corners of each face.
const glm::dvec3 kCorners[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string asciiPly() {
    std::string s = "ply\nformat ascii 1.0\ncomment a tetrahedron\nelement vertex 4\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
    for (const glm::dvec3& c : kCorners) s += fmt::format("{} {} {}\n", c.x, c.y, c.z);
    for (const auto& f : kFaces) s += fmt::format("3 {} {} {}\n", f[0], f[1], f[2]);
    return s;
}

std::string binaryPly() {
    Bytes b;
    b.data = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
             "property float y\nproperty float z\nelement face 4\n"
             "property list uchar int vertex_indices\nend_header\n";
    for (const glm::dvec3& c : kCorners) b.put(float(c.x)).put(float(c.y)).put(float(c.z));
    for (const auto& f : kFaces) b.put(uint8_t{3}).put(f[0]).put(f[1]).put(f[2]);
    return b.data;
}

std::string binaryStl(uint32_t declared = 4) {
    Bytes b;
    b.data = std::string(80, ' ');
    b.put(declared);
    for (const auto& f : kFaces) {
        b.put(0.0f).put(0.0f).put(0.0f); // the facet normal, which readers recompute
        for (int k : f)
            b.put(float(kCorners[k].x)).put(float(kCorners[k].y)).put(float(kCorners[k].z));
        b.put(uint16_t{0});
    }
    return b.data;
}

std::string asciiStl() {
    std::string s = "solid tetrahedron\n";
    for (const auto& f : kFaces) {
        s += "facet normal 0 0 0\nouter loop\n";
        for (int k : f)
            s += fmt::format("vertex {} {} {}\n", kCorners[k].x, kCorners[k].y, kCorners[k].z);
        s += "endloop\nendfacet\n";
    }
    return s + "endsolid tetrahedron\n";
}

/// The tetrahedron's buffer (positions, then 16-bit indices) and a glTF naming it as `uri`,
/// its node moved by `translation`.
std::string gltfBuffer() {
    Bytes b;
    for (const glm::dvec3& c : kCorners) b.put(float(c.x)).put(float(c.y)).put(float(c.z));
    for (const auto& f : kFaces)
        for (int k : f) b.put(uint16_t(k));
    return b.data;
}
std::string gltf(const std::string& uri, const std::string& translation = "[0, 0, 0]") {
    return fmt::format(R"({{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
"nodes": [{{"mesh": 0, "translation": {}}}],
"meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
"buffers": [{{"uri": "{}", "byteLength": 72}}],
"bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                {{"buffer": 0, "byteOffset": 48, "byteLength": 24}}],
"accessors": [{{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 1]}},
              {{"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}}]}})",
                       translation, uri);
}

/// The triangles as sets of corner positions, whatever the order of the vertices.
std::set<std::array<double, 9>> trianglesOf(const MeshData& mesh, glm::dvec3 offset = {}) {
    std::set<std::array<double, 9>> out;
    for (const MeshData::Triangle& t : mesh.triangles) {
        std::array<double, 9> corners{};
        // Rotated so that the least corner comes first: the winding is kept.
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (std::lexicographical_compare(
                    &mesh.positions[t.v[k]].x, &mesh.positions[t.v[k]].x + 3,
                    &mesh.positions[t.v[first]].x, &mesh.positions[t.v[first]].x + 3))
                first = k;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p = mesh.positions[t.v[(first + k) % 3]] - offset;
            corners[3 * k] = p.x, corners[3 * k + 1] = p.y, corners[3 * k + 2] = p.z;
        }
        out.insert(corners);
    }
    return out;
}

const std::set<std::array<double, 9>>& tetrahedron() {
    static const std::set<std::array<double, 9>> kTriangles = [] {
        MeshData m;
        m.positions.assign(std::begin(kCorners), std::end(kCorners));
        for (const auto& f : kFaces)
            m.triangles.push_back({{f[0], f[1], f[2]}, {-1, -1, -1}, {-1, -1, -1}});
        return trianglesOf(m);
    }();
    return kTriangles;
}

MeshData readOk(const std::string& path, const crt::scene::FileGate& gate = {}) {
    MeshFileError error;
    std::optional<MeshData> mesh =
        crt::scene::readAssimpMesh(path, kDefaultMaxMeshSize, gate, error);
    INFO(path << ": " << error.message);
    REQUIRE(mesh);
    return *mesh;
}

std::string readError(const std::string& path, uint64_t maxSize = kDefaultMaxMeshSize,
                      bool* overLimit = nullptr) {
    MeshFileError error;
    CHECK_FALSE(crt::scene::readAssimpMesh(path, maxSize, {}, error));
    CHECK_FALSE(error.message.empty());
    if (overLimit) *overLimit = error.overLimit;
    return error.message;
}

} // namespace

TEST_CASE("mesh files: the same tetrahedron in every format") {
    TempFolder folder("formats");
    folder.write("tetrahedron.bin", gltfBuffer());
    for (const std::string& path :
         {folder.write("ascii.ply", asciiPly()), folder.write("binary.PLY", binaryPly()),
          folder.write("binary.stl", binaryStl()), folder.write("ascii.stl", asciiStl()),
          folder.write("tetrahedron.gltf", gltf("tetrahedron.bin"))}) {
        INFO(path);
        CHECK(crt::scene::isAssimpMeshFile(path));
        const MeshData mesh = readOk(path);
        CHECK(trianglesOf(mesh) == tetrahedron());
        // Corners are shared, STL's too (it stores three a triangle).
        CHECK(mesh.positions.size() == 4);
        CHECK(mesh.normals.empty());
        CHECK(mesh.uvs.empty());
    }
    CHECK_FALSE(crt::scene::isAssimpMeshFile("model.obj"));
    CHECK_FALSE(crt::scene::isAssimpMeshFile("ply/model"));
}

TEST_CASE("mesh files: normals, UVs, polygons and node transforms") {
    TempFolder folder("attributes");
    const std::string quad = folder.write(
        "quad.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                    "property float s\nproperty float t\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n"
                    "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n"
                    "4 0 1 2 3\n");
    const MeshData mesh = readOk(quad);
    REQUIRE(mesh.triangles.size() == 2); // the quad, fan-triangulated
    REQUIRE(mesh.normals.size() == 4);
    REQUIRE(mesh.uvs.size() == 4);
    for (const MeshData::Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            CHECK(mesh.normals[t.n[k]] == glm::dvec3(0, 0, 1));
            CHECK(mesh.uvs[t.uv[k]] == glm::dvec2(mesh.positions[t.v[k]]));
        }
    }
    folder.write("tetrahedron.bin", gltfBuffer());
    const MeshData moved = readOk(folder.write("moved.gltf", gltf("tetrahedron.bin", "[1, 2, 3]")));
    CHECK(trianglesOf(moved, {1, 2, 3}) == tetrahedron());
}

TEST_CASE("mesh files: a glTF's buffer is read only where the gate allows") {
    TempFolder folder("gate");
    const std::string buffer = folder.write("tetrahedron.bin", gltfBuffer());
    const std::string path = folder.write("tetrahedron.gltf", gltf("tetrahedron.bin"));
    // Allowed: read. (The file is read in a child process, so the gate is asked there.)
    readOk(path, [&](const std::string&) { return std::string(); });
    MeshFileError error;
    CHECK_FALSE(crt::scene::readAssimpMesh(
        path, kDefaultMaxMeshSize,
        [&](const std::string& file) {
            return file == buffer ? std::string("is outside the readable folders") : std::string();
        },
        error));
    CHECK_THAT(error.message, Catch::Contains("'" + buffer + "' is outside the readable folders"));
}

TEST_CASE("mesh files: damaged files are errors, never crashes or huge allocations") {
    TempFolder folder("damaged");
    std::string ply = binaryPly();
    CHECK_FALSE(readError(folder.write("cut.ply", ply.substr(0, ply.size() - 10))).empty());
    CHECK_FALSE(readError(folder.write("header.ply", "ply\nformat ascii 1.0\n")).empty());
    // Counts a tiny file cannot hold: refused before Assimp reserves room for them.
    const std::string huge = "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    CHECK(
        readError(folder.write("huge.ply", huge + std::string(16, '\0'))) ==
        "its header declares 2000000000 vertex elements, more than its 16 bytes of data can hold");
    // A header Assimp would read forever (a fuzzing finding): refused line by line.
    CHECK(
        readError(folder.write("tangled.ply", "ply\nformat ascii 1.0\nelemenend_headert vertex 4\n"
                                              "property float x\nend_header\n0\n")) ==
        "line 3 of its PLY header is not one Assimp reads");
    // A GLB chunk longer than the file (Assimp allocated what it declared: a fuzzing finding).
    Bytes glb;
    glb.put(uint32_t{0x46546C67}).put(uint32_t{2}).put(uint32_t{28});
    glb.put(uint32_t{0x40000000}).put(uint32_t{0x4E4F534A}).put(uint64_t{0});
    CHECK(readError(folder.write("chunk.glb", glb.data)) ==
          "its chunk at byte 12 runs past the end of the file");
    CHECK_THAT(readError(folder.write("huge.stl", binaryStl(2000000000))), Catch::Contains("STL"));
    CHECK_FALSE(
        readError(folder.write("text.ply", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).empty());
    CHECK_FALSE(readError(folder.write("empty.glb", "")).empty());
    CHECK_FALSE(readError(folder.write("missing_buffer.gltf", gltf("nowhere.bin"))).empty());
    CHECK_FALSE(readError((folder.path / "absent.stl").string()).empty());
}

TEST_CASE("mesh files: the size limit") {
    TempFolder folder("limit");
    const std::string path = folder.write("tetrahedron.ply", asciiPly());
    bool overLimit = false;
    CHECK(readError(path, 3, &overLimit) == "more than 3 vertices");
    CHECK(overLimit);
    MeshFileError error;
    CHECK(crt::scene::readAssimpMesh(path, 4, {}, error)); // exactly at the limit
}

TEST_CASE("mesh files: readMeshFile picks the reader by the name") {
    TempFolder folder("dispatch");
    std::string error;
    CHECK(crt::scene::readMeshFile(folder.write("t.stl", binaryStl()), kDefaultMaxMeshSize, error));
    const std::string obj = folder.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK(crt::scene::readMeshFile(obj, kDefaultMaxMeshSize, error));
    const std::string bad = folder.write("bad.ply", "ply\n");
    CHECK_FALSE(crt::scene::readMeshFile(bad, kDefaultMaxMeshSize, error));
    CHECK(error.starts_with(bad + ": "));
}
