// The OBJ reader (every face form, relative indices, errors) and mesh triangles.
#include "geometry_test_support.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace crt::tracer;
using namespace crt::tracer::test;

namespace {

MeshData parseOk(std::string_view text) {
    std::string error;
    std::optional<MeshData> mesh = parseObj(text, "mesh.obj", error);
    INFO(error);
    REQUIRE(mesh);
    CHECK(error.empty());
    return *mesh;
}

std::string parseError(std::string_view text) {
    std::string error;
    CHECK_FALSE(parseObj(text, "bad.obj", error));
    return error;
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

TEST_CASE("obj: reading files") {
    namespace fs = std::filesystem;
    fs::path path = fs::temp_directory_path() / "crt_geometry_obj_test.obj";
    {
        std::ofstream out(path, std::ios::binary);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }
    std::string error;
    std::optional<MeshData> mesh = readObj(path.string(), error);
    REQUIRE(mesh);
    CHECK(mesh->triangles.size() == 1);
    fs::remove(path);
    CHECK_FALSE(readObj(path.string(), error));
    CHECK(error == "cannot read '" + path.string() + "'");
    CHECK_FALSE(readObj(fs::temp_directory_path().string(), error)); // a directory
    CHECK(error == "cannot read '" + fs::temp_directory_path().string() + "'");
    {
        std::ofstream out(path, std::ios::binary);
        out << "v 0 0 0\nf 1 1\n";
    }
    CHECK_FALSE(readObj(path.string(), error));
    CHECK(error == path.string() + ":2: face with 2 vertices (at least 3 needed)");
    fs::remove(path);
}

TEST_CASE("mesh triangle: interpolated normals and UVs") {
    auto mesh =
        std::make_shared<MeshData>(parseOk("v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                           "vt 0 0\nvt 1 0\nvt 0 1\n"
                                           "vn 0 0 -1\nvn 1 0 -1\nvn 0 1 -1\n"
                                           "f 1/1/1 2/2/2 3/3/3\nf 1 2 3\nf 1//1 2//2 3//3\n"));
    MeshTriangleGeometry g(mesh, 0);
    CHECK_FALSE(g.solid());
    Ray ray{{0.25, 0.25, 1}, {0, 0, -1}};
    CrossingList list;
    g.crossLine(ray, list);
    REQUIRE(list.count == 1);
    SurfacePoint sp = g.surfaceAt(ray, list.items[0]);
    CHECK(sp.uv.x == Approx(0.25));
    CHECK(sp.uv.y == Approx(0.25));
    checkUnit(sp.shadingNormal);
    CHECK(glm::length(sp.shadingNormal - glm::normalize(Vec3(0.25, 0.25, -1))) < 1e-12);
    // The winding says +z, the vertex normals say −z: the geometric normal follows them.
    CHECK(sp.normal == Vec3(0, 0, -1));
    CHECK(sp.point == Vec3(0.25, 0.25, 0));

    MeshTriangleGeometry plain(mesh, 1); // no normals, no UVs
    sp = plain.surfaceAt(ray, list.items[0]);
    CHECK(sp.normal == Vec3(0, 0, 1));
    CHECK(sp.shadingNormal == sp.normal);
    CHECK(sp.uv.x == Approx(0.25)); // barycentric

    MeshTriangleGeometry outOfRange(mesh, 7);
    outOfRange.crossLine(ray, list);
    CHECK(list.count == 0);
    CHECK(outOfRange.bounds().empty());
}
