// The terrain of bench/embree/run.sh (see bench/README.md, "Ray kernel vs Embree 3"): the
// triangle mesh bench/render/gen_terrain.py writes as a binary PLY file, one
// RTC_GEOMETRY_TYPE_TRIANGLE geometry on the file's own vertex and index arrays (shared
// buffers), rendered by harness.hpp's camera, light and shading. Built by run.sh only; crtc
// does not depend on it.
#include "harness.hpp"

#include <algorithm>
#include <cerrno>
#include <memory>
#include <sstream>

namespace {

constexpr const char* kUsage = "--ply FILE";

struct Mesh {
    std::vector<float> positions;    ///< x, y, z a vertex, then one float of padding
    std::vector<uint32_t> indices;   ///< three a triangle
    size_t vertexCount = 0, triangleCount = 0;
};

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), why.c_str());
    std::exit(1);
}

/// Reads the layout gen_terrain.py writes, and refuses any other: little-endian vertices of
/// float x, y, z only, then faces of a uchar count and int indices only. Embree does not check
/// indices, so each is checked here.
Mesh readPly(const std::string& path) {
    const uint32_t one = 1;
    unsigned char firstByte;
    std::memcpy(&firstByte, &one, 1);
    if (firstByte != 1) fail(path, "this reader needs a little-endian machine");

    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) fail(path, std::strerror(errno));
    FILE* f = file.get();
    std::vector<std::string> header;
    char line[512];
    while (std::fgets(line, sizeof line, f)) {
        std::string text(line);
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
        if (text.rfind("comment", 0) == 0) continue;
        if (text == "end_header") break;
        header.push_back(text);
    }
    Mesh mesh;
    const std::vector<std::string> expected = {
        "ply", "format binary_little_endian 1.0", "element vertex", "property float x", "property float y",
        "property float z", "element face", "property list uchar int vertex_indices"};
    bool layout = header.size() == expected.size();
    for (size_t i = 0; layout && i < expected.size(); ++i) {
        if (i == 2 || i == 6) {
            std::istringstream words(header[i]);
            std::string element, name;
            size_t count = 0;
            layout = bool(words >> element >> name >> count) && element + " " + name == expected[i];
            size_t& counted = i == 2 ? mesh.vertexCount : mesh.triangleCount;
            counted = count;
        } else {
            layout = header[i] == expected[i];
        }
    }
    if (!layout) fail(path, "not the binary PLY layout gen_terrain.py writes");
    // Bounded like crtc's --max-mesh-size, so a damaged header cannot ask for terabytes.
    if (mesh.vertexCount < 3 || mesh.vertexCount > 10000000 || mesh.triangleCount < 1 ||
        mesh.triangleCount > 10000000)
        fail(path, "vertex or face count out of range");

    mesh.positions.resize(3 * mesh.vertexCount + 1); // Embree reads the last vertex as 16 bytes
    if (std::fread(mesh.positions.data(), 3 * sizeof(float), mesh.vertexCount, f) != mesh.vertexCount)
        fail(path, "the file ends within its vertices");
    mesh.indices.resize(3 * mesh.triangleCount);
    constexpr size_t kRecord = 1 + 3 * sizeof(int32_t);
    std::vector<unsigned char> block(kRecord * 65536);
    for (size_t done = 0; done < mesh.triangleCount;) {
        const size_t want = std::min(mesh.triangleCount - done, block.size() / kRecord);
        if (std::fread(block.data(), kRecord, want, f) != want) fail(path, "the file ends within its faces");
        for (size_t k = 0; k < want; ++k, ++done) {
            const unsigned char* record = block.data() + k * kRecord;
            if (record[0] != 3) fail(path, "face " + std::to_string(done) + " is not a triangle");
            for (int c = 0; c < 3; ++c) {
                int32_t index;
                std::memcpy(&index, record + 1 + c * sizeof(int32_t), sizeof index);
                if (index < 0 || size_t(index) >= mesh.vertexCount)
                    fail(path, "face " + std::to_string(done) + " names vertex " + std::to_string(index));
                mesh.indices[3 * done + size_t(c)] = uint32_t(index);
            }
        }
    }
    return mesh;
}

void attachMesh(RTCDevice device, RTCScene scene, const Mesh& mesh) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               mesh.positions.data(), 0, 3 * sizeof(float), mesh.vertexCount);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(),
                               0, 3 * sizeof(uint32_t), mesh.triangleCount);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

} // namespace

int main(int argc, char** argv) {
    std::string ply;
    auto plyOption = [&](const std::string& name, const char* value) {
        if (name != "--ply") return false;
        ply = value;
        return true;
    };
    const harness::View view = harness::parseView(argc, argv, kUsage, plyOption);
    if (ply.empty()) harness::usage(argv[0], kUsage);
    const Mesh mesh = readPly(ply);
    return harness::run(view, "triangles " + std::to_string(mesh.triangleCount),
                        [&](RTCDevice device, RTCScene scene) { attachMesh(device, scene, mesh); });
}
