// The OBJ reader (every face form, relative indices, errors) and mesh triangles.
#include "geometry_test_support.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace crt::tracer;
using namespace crt::tracer::test;

namespace {

using crt::scene::kDefaultMaxMeshSize;
using crt::scene::ObjError;
using crt::scene::readObj;

MeshData parseOk(std::string_view text) {
    ObjError error;
    std::optional<MeshData> mesh = crt::scene::parseObj(text, kDefaultMaxMeshSize, error);
    INFO(error.message);
    REQUIRE(mesh);
    CHECK(error.message.empty());
    return *mesh;
}

ObjError parseFailure(std::string_view text, uint64_t maxSize = kDefaultMaxMeshSize) {
    ObjError error;
    CHECK_FALSE(crt::scene::parseObj(text, maxSize, error));
    return error;
}

std::string parseError(std::string_view text) { return parseFailure(text).describe("bad.obj"); }

/// The bytes an error is about.
std::string_view blamed(std::string_view text, const ObjError& error) {
    return text.substr(error.begin, error.end - error.begin);
}

void checkTriangle(const MeshData::Triangle& t, std::array<int, 3> v, std::array<int, 3> uv,
                   std::array<int, 3> n) {
    for (int k = 0; k < 3; ++k) {
        CHECK(t.v[k] == v[size_t(k)]);
        CHECK(t.uv[k] == uv[size_t(k)]);
        CHECK(t.n[k] == n[size_t(k)]);
    }
}

} // namespace

TEST_CASE("obj: vertices, normals, UVs and every face form") {
    MeshData m = parseOk("# a comment\n"
                         "mtllib scene.mtl\n"
                         "o thing\n"
                         "v 0 0 0\n"
                         "v 1 0 0 1.0\n" // an optional w
                         "v 0 1 0\n"
                         "v 1 1 0\n"
                         "vt 0 0\n"
                         "vt 1 0\n"
                         "vt 0.5\n" // v defaults to 0
                         "vn 0 0 1\n"
                         "g part\n"
                         "usemtl red\n"
                         "s off\n"
                         "f 1 2 3\n"
                         "f 1/1 2/2 3/3\n"
                         "f 1//1 2//1 3//1\n"
                         "f 2/1/1 4/2/1 3/3/1   # trailing comment\n");
    REQUIRE(m.positions.size() == 4);
    CHECK(m.positions[1] == Vec3(1, 0, 0));
    REQUIRE(m.uvs.size() == 3);
    CHECK(m.uvs[2] == Vec2(0.5, 0));
    REQUIRE(m.normals.size() == 1);
    REQUIRE(m.triangles.size() == 4);
    checkTriangle(m.triangles[0], {0, 1, 2}, {-1, -1, -1}, {-1, -1, -1});
    checkTriangle(m.triangles[1], {0, 1, 2}, {0, 1, 2}, {-1, -1, -1});
    checkTriangle(m.triangles[2], {0, 1, 2}, {-1, -1, -1}, {0, 0, 0});
    checkTriangle(m.triangles[3], {1, 3, 2}, {0, 1, 2}, {0, 0, 0});
}

TEST_CASE("obj: negative indices count back from the latest element") {
    MeshData m =
        parseOk("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf -3/-1/-1 -2/-1/-1 -1/-1/-1\n"
                "v 5 5 5\nf -4 -1 -2\n");
    REQUIRE(m.triangles.size() == 2);
    checkTriangle(m.triangles[0], {0, 1, 2}, {0, 0, 0}, {0, 0, 0});
    checkTriangle(m.triangles[1], {0, 3, 2}, {-1, -1, -1}, {-1, -1, -1});
}

TEST_CASE("obj: polygons are fan-triangulated, CRLF and blank lines are fine") {
    MeshData m =
        parseOk("v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\n\r\nv 0.5 1.5 0\r\nv 0 1 0\r\n\tf 1 2 3 4 5\r\n");
    REQUIRE(m.triangles.size() == 3);
    checkTriangle(m.triangles[0], {0, 1, 2}, {-1, -1, -1}, {-1, -1, -1});
    checkTriangle(m.triangles[1], {0, 2, 3}, {-1, -1, -1}, {-1, -1, -1});
    checkTriangle(m.triangles[2], {0, 3, 4}, {-1, -1, -1}, {-1, -1, -1});
    CHECK(m.positions[3] == Vec3(0.5, 1.5, 0));
    CHECK(parseOk("").triangles.empty());
    CHECK(parseOk("v 1e-3 -2.5E+2 +3\n").positions[0] == Vec3(1e-3, -250, 3));
}

TEST_CASE("obj: errors name the file and line") {
    CHECK(parseError("v 0 0 0\nv 1 x 0\n") == "bad.obj:2: bad number 'x'");
    CHECK(parseError("v 0 0\n") == "bad.obj:1: expected 3 numbers, found 2");
    CHECK(parseError("vn 0 0 1e999\n") == "bad.obj:1: bad number '1e999'");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n") ==
          "bad.obj:5: vertex index 4 out of range (3 defined)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n") ==
          "bad.obj:4: vertex index 0 out of range (3 defined)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n") ==
          "bad.obj:4: vertex index -4 out of range (3 defined)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n") ==
          "bad.obj:4: texture coordinate index 1 out of range (0 defined)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n") ==
          "bad.obj:5: normal index 2 out of range (1 defined)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nf 1 2\n") ==
          "bad.obj:3: face with 2 vertices (at least 3 needed)");
    CHECK(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 3\n") == "bad.obj:4: bad vertex index 'a'");
    CHECK(parseError("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3 0\r\n") ==
          "bad.obj:4: vertex index 0 out of range (3 defined)");
}

TEST_CASE("obj: an error points at the bytes it is about") {
    const std::string_view badIndex = "v 0 0 0\nv 1 0 0\nv 0 1 0\n  f 1 2 -7/1  # far\n";
    ObjError e = parseFailure(badIndex);
    CHECK(e.line == 4);
    CHECK(blamed(badIndex, e) == "-7"); // the vertex part of the corner "-7/1"
    const std::string_view shortFace = "v 0 0 0\r\n\tf 1 1 \r\n";
    e = parseFailure(shortFace);
    CHECK(blamed(shortFace, e) == "f 1 1"); // the whole statement, without blanks around it
    const std::string_view badNumber = "vt 0.5 .5x\n";
    CHECK(blamed(badNumber, parseFailure(badNumber)) == ".5x");
    CHECK(parseFailure("\x01\x02\0").line == 0); // binary: about the whole file
    CHECK(parseError("hello\nworld\n") ==
          "bad.obj: not a Wavefront OBJ mesh (no line of it is an OBJ statement)");
}

TEST_CASE("obj: sizes above the limit are refused before they are stored") {
    const std::string_view quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    ObjError e = parseFailure(quad, 3);
    CHECK(e.overLimit);
    CHECK(e.line == 4);
    CHECK(e.message == "more than 3 vertices");
    e = parseFailure("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nf 1 2 3\nf 3 2 1 # 4th\n", 3);
    CHECK(e.message == "more than 3 triangles");
    CHECK(e.line == 7);
    CHECK(parseFailure("vn 0 0 1\nvn 0 0 1\n", 1).message == "more than 1 normals");
    CHECK(parseFailure("vt 0 0\nvt 0 0\n", 1).message == "more than 1 texture coordinates");
    ObjError ok;
    CHECK(crt::scene::parseObj(quad, 4, ok)); // exactly at the limit
    CHECK_FALSE(parseFailure("v 0 0\n", 1).overLimit);
}

TEST_CASE("obj: reading files") {
    namespace fs = std::filesystem;
    fs::path path = fs::temp_directory_path() / "crt_geometry_obj_test.obj";
    {
        std::ofstream out(path, std::ios::binary);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }
    std::string error;
    std::optional<MeshData> mesh = readObj(path.string(), kDefaultMaxMeshSize, error);
    REQUIRE(mesh);
    CHECK(mesh->triangles.size() == 1);
    fs::remove(path);
    CHECK_FALSE(readObj(path.string(), kDefaultMaxMeshSize, error));
    CHECK(error == "cannot read '" + path.string() + "'");
    CHECK_FALSE(readObj(fs::temp_directory_path().string(), kDefaultMaxMeshSize, error)); // a directory
    CHECK(error == "cannot read '" + fs::temp_directory_path().string() + "'");
    {
        std::ofstream out(path, std::ios::binary);
        out << "v 0 0 0\nf 1 1\n";
    }
    CHECK_FALSE(readObj(path.string(), kDefaultMaxMeshSize, error));
    CHECK(error == path.string() + ":2: face with 2 vertices (at least 3 needed)");
    fs::remove(path);
}

TEST_CASE("mesh: interpolated normals and UVs, each crossing naming its triangle") {
    auto data =
        std::make_shared<MeshData>(parseOk("v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                           "vt 0 0\nvt 1 0\nvt 0 1\n"
                                           "vn 0 0 -1\nvn 1 0 -1\nvn 0 1 -1\n"
                                           "f 1/1/1 2/2/2 3/3/3\nf 1 2 3\nf 1//1 2//2 3//3\n"));
    MeshGeometry g(std::make_shared<const TriangleMesh>(data));
    CHECK_FALSE(g.solid());
    Ray ray{{0.25, 0.25, 1}, {0, 0, -1}};
    CrossingList list;
    g.crossLine(ray, list);
    REQUIRE(list.count == 3); // the three triangles lie on one another
    Crossing first{list[0].t, 0};
    SurfacePoint sp = g.surfaceAt(ray, first);
    CHECK(sp.uv.x == Approx(0.25));
    CHECK(sp.uv.y == Approx(0.25));
    checkUnit(sp.shadingNormal);
    CHECK(glm::length(sp.shadingNormal - glm::normalize(Vec3(0.25, 0.25, -1))) < 1e-12);
    // The face turns toward its vertex normals.
    CHECK(sp.normal == Vec3(0, 0, -1));
    CHECK(sp.point == Vec3(0.25, 0.25, 0));

    sp = g.surfaceAt(ray, Crossing{list[0].t, 1}); // no normals, no UVs
    CHECK(sp.normal == Vec3(0, 0, 1));
    CHECK(sp.shadingNormal == sp.normal);
    CHECK(sp.uv.x == Approx(0.25)); // barycentric

    Crossing nearest{};
    REQUIRE(g.firstCrossingIn(ray, 0, kInfinity, nearest, kNoPart));
    CHECK(nearest.t == 1);
    // The face a ray leaves from is not met again; the others still are.
    int met = 0;
    auto count = [&](const Crossing& c) {
        CHECK(c.part != 1);
        ++met;
        return true;
    };
    g.crossingsIn(ray, 0, kInfinity, count, 1);
    CHECK(met == 2);
}

TEST_CASE("mesh: triangles out of range, not finite or of no area are crossed by no line") {
    auto data = std::make_shared<MeshData>();
    data->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {kInfinity, 0, 0}};
    data->triangles = {{{0, 1, 7}, {-1, -1, -1}, {-1, -1, -1}},
                       {{0, 1, 3}, {-1, -1, -1}, {-1, -1, -1}},
                       {{0, 1, 4}, {-1, -1, -1}, {-1, -1, -1}}};
    MeshGeometry g(std::make_shared<const TriangleMesh>(data));
    CHECK(g.bounds().empty());
    CrossingList list;
    g.crossLine(Ray{{0.5, 0, 1}, {0, 0, -1}}, list);
    CHECK(list.count == 0);
    data->triangles.push_back({{0, 1, 2}, {-1, -1, -1}, {-1, -1, -1}});
    MeshGeometry one(std::make_shared<const TriangleMesh>(data));
    one.crossLine(Ray{{0.25, 0.25, 1}, {0, 0, -1}}, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].part == 3);
}

TEST_CASE("mesh: crossings come as the BVH finds them, each once, and stop at the first the visitor refuses") {
    // 40 unit squares stacked along z, two triangles each; a ray along z crosses one of each.
    auto data = std::make_shared<MeshData>();
    for (int layer = 0; layer < 40; ++layer) {
        const auto first = static_cast<int32_t>(data->positions.size());
        const double z = layer;
        data->positions.insert(data->positions.end(), {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}});
        data->triangles.push_back({{first, first + 1, first + 2}, {-1, -1, -1}, {-1, -1, -1}});
        data->triangles.push_back({{first, first + 2, first + 3}, {-1, -1, -1}, {-1, -1, -1}});
    }
    const MeshGeometry g(std::make_shared<const TriangleMesh>(data));
    const Ray ray{{0.7, 0.2, -1}, {0, 0, 1}};
    std::vector<std::pair<double, uint32_t>> met;
    auto collect = [&](const Crossing& c) {
        met.emplace_back(c.t, c.part);
        return true;
    };
    const uint32_t skipped = 2 * 5; // the first triangle of layer 5, which the ray crosses
    CHECK(g.crossingsIn(ray, 3.5, 30.5, collect, skipped));
    // Layers 3 to 29 but 5, each through its first triangle (the point has y < x), at z + 1.
    std::vector<std::pair<double, uint32_t>> expected;
    for (int layer = 3; layer <= 29; ++layer)
        if (layer != 5) expected.emplace_back(layer + 1, 2 * layer);
    std::sort(met.begin(), met.end());
    REQUIRE(met.size() == expected.size());
    for (size_t i = 0; i < met.size(); ++i) {
        CHECK(met[i].first == Approx(expected[i].first).epsilon(1e-12));
        CHECK(met[i].second == expected[i].second);
    }
    int visits = 0;
    auto refuse = [&](const Crossing&) {
        ++visits;
        return false;
    };
    CHECK_FALSE(g.crossingsIn(ray, 0, kInfinity, refuse, kNoPart));
    CHECK(visits == 1);
}
