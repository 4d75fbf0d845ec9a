// Work run in a child process: its bytes come back, however many; a child that dies or
// fails gives an error, not the parent's death. And a mesh (or why there is none) as bytes
// and back, which is how a mesh read in a child returns.
#include "geometry_test_support.hpp"

#include "scene/child_process.hpp"
#include "scene/mesh_bytes.hpp"

#include <csignal>
#include <unistd.h>

using crt::scene::inChildProcess;
using crt::scene::MeshData;
using crt::scene::MeshFileError;

TEST_CASE("child process: the work's bytes come back") {
    std::string why;
    CHECK(inChildProcess([] { return std::string("tetrahedron"); }, 1 << 30, why) == "tetrahedron");
    // More than a pipe holds at once, with every byte value.
    std::string big(10'000'000, '\0');
    for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7);
    CHECK(inChildProcess([&] { return big; }, 1 << 30, why) == big);
    CHECK(inChildProcess([] { return std::string(); }, 1 << 30, why) == "");
    // Above the bound: refused, not taken in.
    CHECK_FALSE(inChildProcess([] { return std::string(100, 'x'); }, 99, why));
    CHECK(why == "its answer of 100 bytes is longer than it may be");
}

TEST_CASE("child process: a child that dies is an error of the parent") {
    std::string why;
    CHECK_FALSE(inChildProcess(
        []() -> std::string {
            ::kill(::getpid(), SIGKILL);
            return "unreached";
        },
        1 << 30, why));
    CHECK_THAT(why, Catch::StartsWith("it stopped on signal 9"));
    CHECK_FALSE(inChildProcess([]() -> std::string { ::_exit(3); }, 1 << 30, why));
    CHECK(why == "it stopped with status 3");
}

TEST_CASE("mesh bytes: a mesh and an error round-trip, damaged bytes do not") {
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}};
    mesh.uvs = {{0, 0}, {1, 0.25}, {0, 1}};
    mesh.triangles.push_back({{0, 1, 2}, {-1, -1, -1}, {0, 1, 2}});
    mesh.closed = true;
    mesh.inward = true;
    MeshFileError error;
    const std::string bytes = crt::scene::meshToBytes(mesh, error);
    std::optional<MeshData> back = crt::scene::meshFromBytes(bytes, error);
    REQUIRE(back);
    CHECK(back->positions == mesh.positions);
    CHECK(back->normals.empty());
    CHECK(back->uvs == mesh.uvs);
    REQUIRE(back->triangles.size() == 1);
    CHECK(back->triangles[0].uv[2] == 2);
    CHECK(back->closed);
    CHECK(back->inward);

    const std::string failure = crt::scene::meshToBytes(std::nullopt, {"no triangles", true});
    CHECK_FALSE(crt::scene::meshFromBytes(failure, error));
    CHECK(error.message == "no triangles");
    CHECK(error.overLimit);

    for (size_t cut : {size_t{0}, size_t{1}, bytes.size() / 2, bytes.size() - 1}) {
        CHECK_FALSE(crt::scene::meshFromBytes(std::string_view(bytes).substr(0, cut), error));
        CHECK(error.message == "the reader's answer was cut short");
    }
}
