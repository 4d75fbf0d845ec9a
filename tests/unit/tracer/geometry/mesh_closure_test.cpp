// Whether a mesh bounds a solid: closed and consistently wound, whichever way round, with
// split vertices joined by position; the edge an open mesh is named by.
#include "geometry_test_support.hpp"

#include "scene/mesh_closure.hpp"

using crt::scene::MeshClosure;
using crt::scene::meshClosure;
using crt::tracer::MeshData;

namespace {

MeshData meshOf(std::vector<glm::dvec3> positions, std::vector<std::array<int32_t, 3>> faces) {
    MeshData m;
    m.positions = std::move(positions);
    for (const auto& f : faces)
        m.triangles.push_back({{f[0], f[1], f[2]}, {-1, -1, -1}, {-1, -1, -1}});
    return m;
}

/// An edge by its smaller vertex number, then its larger.
std::pair<int32_t, int32_t> edge(int32_t a, int32_t b) {
    return {std::min(a, b), std::max(a, b)};
}

/// The first of a triangle's edges: the one an open mesh names where only that triangle is
/// missing.
std::pair<int32_t, int32_t> firstEdgeOf(const std::array<int32_t, 3>& t) {
    return std::min({edge(t[0], t[1]), edge(t[1], t[2]), edge(t[2], t[0])});
}

const std::vector<glm::dvec3> kCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::array<int32_t, 3>> kOutward = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

} // namespace

TEST_CASE("mesh closure: a tetrahedron wound either way is closed") {
    MeshClosure out = meshClosure(meshOf(kCorners, kOutward));
    CHECK(out.closed);
    CHECK_FALSE(out.inward);
    std::vector<std::array<int32_t, 3>> inward;
    for (auto f : kOutward) inward.push_back({f[0], f[2], f[1]});
    MeshData in = meshOf(kCorners, inward);
    out = crt::scene::markClosure(in);
    CHECK(out.closed);
    CHECK(out.inward);
    CHECK(in.closed);
    CHECK(in.inward);
}

TEST_CASE("mesh closure: split vertices count as one, flat triangles not at all") {
    // A soup: three vertices of its own for each triangle, as STL stores them.
    MeshData soup;
    for (const auto& f : kOutward) {
        const auto first = static_cast<int32_t>(soup.positions.size());
        for (int32_t k : f) soup.positions.push_back(kCorners[size_t(k)]);
        soup.triangles.push_back({{first, first + 1, first + 2}, {-1, -1, -1}, {-1, -1, -1}});
    }
    // And a triangle with no area, two corners at one place.
    soup.positions.push_back(kCorners[0]);
    soup.triangles.push_back(
        {{0, 1, static_cast<int32_t>(soup.positions.size() - 1)}, {-1, -1, -1}, {-1, -1, -1}});
    CHECK(meshClosure(soup).closed);
}

TEST_CASE("mesh closure: open meshes name an edge") {
    MeshClosure out = meshClosure(meshOf(kCorners, {kOutward[0], kOutward[1], kOutward[2]}));
    CHECK_FALSE(out.closed);
    CHECK(out.problem == "has one triangle");
    CHECK(out.edgeFrom >= 0);
    CHECK(out.edgeTo >= 0);
    // One face turned: every edge has two triangles, but one runs the same way in both.
    auto twisted = kOutward;
    twisted[3] = {1, 3, 2};
    out = meshClosure(meshOf(kCorners, twisted));
    CHECK_FALSE(out.closed);
    CHECK(out.problem == "runs the same way in both of its triangles");
    // Three triangles on one edge.
    auto fin = kOutward;
    fin.push_back({0, 1, 2});
    out = meshClosure(meshOf(kCorners, fin));
    CHECK_FALSE(out.closed);
    CHECK(out.problem == "has 3 triangles");
    out = meshClosure(MeshData{});
    CHECK_FALSE(out.closed);
    CHECK(out.problem == "has no triangles");
}

TEST_CASE("mesh closure: a large torus is closed, and the edge named where it opens is the first") {
    // A torus of n × n quads, two triangles each, its vertices numbered in a shuffled order
    // (row-major numbers times a prime, modulo their count) so that neighbouring vertices are
    // far apart in number: its half edges spread over every part of the sort.
    constexpr int32_t n = 300;
    auto vertex = [](int32_t i, int32_t j) { return ((i % n) * n + j % n) * 7919 % (n * n); };
    const double turn = 2 * std::acos(-1.0) / n;
    std::vector<glm::dvec3> positions(size_t(n) * n);
    for (int32_t i = 0; i < n; ++i)
        for (int32_t j = 0; j < n; ++j) {
            const double u = turn * i, v = turn * j;
            positions[size_t(vertex(i, j))] = {(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)};
        }
    std::vector<std::array<int32_t, 3>> faces;
    for (int32_t i = 0; i < n; ++i)
        for (int32_t j = 0; j < n; ++j) {
            faces.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
            faces.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
        }
    CHECK(meshClosure(meshOf(positions, faces)).closed);
    // Without one triangle, its three edges have one triangle each; the one named is the
    // first by its smaller vertex number, then its larger.
    const std::array<int32_t, 3> removed = faces[12345];
    faces.erase(faces.begin() + 12345);
    const MeshClosure out = meshClosure(meshOf(positions, faces));
    CHECK_FALSE(out.closed);
    CHECK(out.problem == "has one triangle");
    CHECK(edge(out.edgeFrom, out.edgeTo) == firstEdgeOf(removed));
}

TEST_CASE("mesh closure: a vertex with thousands of edges") {
    // A double cone: two apexes and a ring of m vertices, each apex joined to all of them.
    constexpr int32_t m = 3000;
    std::vector<glm::dvec3> positions = {{0, 0, 1}, {0, 0, -1}};
    for (int32_t i = 0; i < m; ++i) {
        const double a = 2 * std::acos(-1.0) * i / m;
        positions.push_back({std::cos(a), std::sin(a), 0});
    }
    std::vector<std::array<int32_t, 3>> faces;
    for (int32_t i = 0; i < m; ++i) {
        const int32_t r = 2 + i, next = 2 + (i + 1) % m;
        faces.push_back({0, r, next});
        faces.push_back({1, next, r});
    }
    MeshClosure out = meshClosure(meshOf(positions, faces));
    CHECK(out.closed);
    CHECK_FALSE(out.inward);
    // Open where one triangle at the upper apex is missing; turned, one at the lower.
    const std::array<int32_t, 3> removed = faces[2 * 1234];
    faces.erase(faces.begin() + 2 * 1234);
    out = meshClosure(meshOf(positions, faces));
    CHECK(out.problem == "has one triangle");
    CHECK(edge(out.edgeFrom, out.edgeTo) == firstEdgeOf(removed));
    faces.insert(faces.begin() + 2 * 1234, removed);
    std::swap(faces[2 * 77 + 1][1], faces[2 * 77 + 1][2]);
    out = meshClosure(meshOf(positions, faces));
    CHECK(out.problem == "runs the same way in both of its triangles");
    CHECK(edge(out.edgeFrom, out.edgeTo) == firstEdgeOf(faces[2 * 77 + 1]));
}

TEST_CASE("mesh closure: the first vertex at each position, by ==") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<glm::dvec3> positions = {{0, 0, 0},   {1, 2, 3},   {-0.0, 0, -0.0}, {1, 2, 3},
                                               {nan, 0, 0}, {nan, 0, 0}, {1, 2, 3.000001}, {0, 0, 0}};
    // -0 is 0; a NaN equals nothing, not even another NaN.
    CHECK(crt::scene::firstVertexAtPosition(positions) == std::vector<int32_t>{0, 1, 0, 1, 4, 5, 6, 0});
}
