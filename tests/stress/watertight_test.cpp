// Watertight meshes: rays through shared edges and vertices of OBJ meshes never slip through.
//
// A tessellated sphere and a cube with gridded faces, written by the test as OBJ files with
// shared vertices, are seen so that many pixel rays meet the mesh exactly on an edge or a
// vertex: looking straight at the sphere's pole (where 32 triangles meet) and along its
// equator (the middle row of rays lies in the equator's plane, the middle column in a
// meridian's), looking at a corner of the cube (the middle column lies in the plane of two of
// its edges), and facing the cube with pixel centres on the grid: every pixel ray meets a grid
// vertex, a grid edge or a cell's diagonal. Each mesh is drawn closed and as its front half
// only (the triangles facing the camera), so a ray that slips through the front surface shows
// the black background instead of the back. The closed mesh is also drawn as a solid, cut by
// a large sphere in CSG, where its crossings must alternate between entering and leaving: a
// line through an edge meets two triangles there, and one missed or one too many would leave
// the line outside. The silhouette comes from the mesh's convex solid (the intersection of its
// face planes, blind to edges); inside it, 0 background pixels.
#include "analytic_shapes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <tuple>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;

namespace {

/// Odd sizes: the middle pixel's ray is the camera's forward direction exactly.
constexpr int kWidth = 97, kHeight = 73;
const scene::Color kEmission{0.9, 0.8, 0.3, 1};

struct Mesh {
    std::vector<DVec3> vertices;
    std::vector<std::array<int, 3>> triangles;
};

/// cos and sin of 2π·k/n, exact at multiples of a quarter turn (so vertices on the axes lie
/// exactly in the axis planes that camera rays run along).
std::pair<double, double> turn(int k, int n) {
    k = ((k % n) + n) % n;
    if ((4 * k) % n == 0) {
        const double c[] = {1, 0, -1, 0};
        int quarter = (4 * k / n) % 4;
        return {c[quarter], c[(quarter + 3) % 4]};
    }
    double a = 2 * test::kTestPi * k / n;
    return {std::cos(a), std::sin(a)};
}

/// A unit sphere of `bands` latitude bands (even: a ring on the equator) and `segments`
/// longitudes, with one vertex at each pole.
Mesh uvSphere(int bands, int segments) {
    Mesh mesh;
    mesh.vertices.push_back({0, -1, 0});
    for (int k = 1; k < bands; ++k) {
        auto [rho, y] = turn(k - bands / 2, 2 * bands); // latitude (k − bands/2)·π/bands
        for (int j = 0; j < segments; ++j) {
            auto [c, s] = turn(j, segments);
            mesh.vertices.push_back({rho * c, y, rho * s});
        }
    }
    mesh.vertices.push_back({0, 1, 0});
    const int top = static_cast<int>(mesh.vertices.size()) - 1;
    auto ring = [&](int k, int j) { return 1 + (k - 1) * segments + (j % segments); };
    for (int j = 0; j < segments; ++j) {
        mesh.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
        mesh.triangles.push_back({top, ring(bands - 1, j), ring(bands - 1, j + 1)});
        for (int k = 1; k + 1 < bands; ++k) {
            mesh.triangles.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
            mesh.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
        }
    }
    return mesh;
}

/// The cube [-1, 1]³ with each face a `cells` × `cells` grid, every cell split along a
/// diagonal; vertices on the cube's edges are shared between faces.
Mesh gridCube(int cells) {
    Mesh mesh;
    std::map<std::tuple<int, int, int>, int> index;
    auto vertex = [&](int a, int b, int c) { // grid coordinates 0..cells
        auto [it, added] = index.try_emplace({a, b, c}, static_cast<int>(mesh.vertices.size()));
        if (added) {
            mesh.vertices.push_back(DVec3(a, b, c) * (2.0 / cells) - DVec3(1.0));
        }
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis) {
        for (int side : {0, cells}) {
            auto at = [&](int i, int j) {
                int g[3];
                g[axis] = side;
                g[(axis + 1) % 3] = i;
                g[(axis + 2) % 3] = j;
                return vertex(g[0], g[1], g[2]);
            };
            for (int i = 0; i < cells; ++i) {
                for (int j = 0; j < cells; ++j) {
                    mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                    mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
                }
            }
        }
    }
    return mesh;
}

DVec3 outwardNormal(const Mesh& mesh, const std::array<int, 3>& t) {
    DVec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    DVec3 n = glm::normalize(glm::cross(b - a, c - a));
    return glm::dot(n, a + b + c) < 0 ? -n : n; // both meshes surround the origin
}

/// The convex solid bounded by the mesh's face planes (coplanar triangles give one plane);
/// requires that it is convex indeed.
std::vector<HalfSpace> solidOf(const Mesh& mesh) {
    std::vector<HalfSpace> faces;
    for (const auto& t : mesh.triangles) {
        HalfSpace h{outwardNormal(mesh, t), mesh.vertices[t[0]]};
        auto samePlane = [&](const HalfSpace& f) {
            return glm::length(f.normal - h.normal) < 1e-12 &&
                   std::abs(glm::dot(f.normal, f.point - h.point)) < 1e-12;
        };
        if (std::none_of(faces.begin(), faces.end(), samePlane)) faces.push_back(h);
    }
    bool convex = true;
    for (const HalfSpace& h : faces)
        for (const DVec3& v : mesh.vertices) convex &= glm::dot(h.normal, v - h.point) < 1e-12;
    REQUIRE(convex);
    return faces;
}

/// The mesh with every triangle's corners in counter-clockwise order seen from outside (the
/// meshes above are built without minding it), as a solid needs.
Mesh outwardWound(const Mesh& mesh) {
    Mesh wound = mesh;
    for (auto& t : wound.triangles) {
        const DVec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
        if (glm::dot(glm::cross(b - a, c - a), outwardNormal(mesh, t)) < 0) std::swap(t[1], t[2]);
    }
    return wound;
}

/// The triangles facing `eye` (what shows of a convex mesh; they cover its silhouette).
Mesh frontHalf(const Mesh& mesh, DVec3 eye) {
    Mesh front{mesh.vertices, {}};
    for (const auto& t : mesh.triangles)
        if (glm::dot(outwardNormal(mesh, t), eye - mesh.vertices[t[0]]) > 0)
            front.triangles.push_back(t);
    return front;
}

/// The mesh as a triangle soup, each triangle shrunk towards its centre by `shrink`: hairline
/// cracks along every edge (the control that shows the check sees leaks).
Mesh cracked(const Mesh& mesh, double shrink) {
    Mesh soup;
    for (const auto& t : mesh.triangles) {
        DVec3 center = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
        int first = static_cast<int>(soup.vertices.size());
        for (int i : t)
            soup.vertices.push_back(center + (1 - shrink) * (mesh.vertices[i] - center));
        soup.triangles.push_back({first, first + 1, first + 2});
    }
    return soup;
}

struct LeakCount {
    int inside = 0;
    int leaks = 0;
    std::string first; ///< the first leaking pixel
};

/// How a mesh is drawn: as triangles, or as a closed solid in CSG (intersected with a sphere
/// holding it, so the result is the mesh's solid).
enum class Drawn { Triangles, Solid };

/// Renders `drawn` flat on black and counts the background pixels inside the silhouette.
LeakCount countLeaks(const Mesh& drawn, const std::vector<HalfSpace>& solid,
                     const scene::CameraDesc& camera, const std::string& fileName,
                     Drawn how = Drawn::Triangles) {
    TempObjFile file(fileName, drawn.vertices, drawn.triangles);
    test::SceneMaker m;
    m.desc = test::blankScene(kWidth, kHeight, camera);
    const int32_t material = flatMaterial(m, kEmission);
    const int32_t mesh = m.entity(scene::MeshShape{file.path(), file.path()}, material);
    if (how == Drawn::Solid)
        m.draw(m.csg(scene::CsgOp::Intersection, mesh, m.sphere(DVec3(0.0), 10, material)));
    else
        m.draw(mesh);
    PixelBuffer image = test::renderOk(m.desc);
    LeakCount count;
    auto hits = [&](const TestRay& r) { return convexHit(r, solid).has_value(); };
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (coverage(m.desc, x, y, 0.01, hits) != Coverage::Inside) continue;
            ++count.inside;
            // A hit is the emission exactly; anything darker than half of it is background.
            if (test::pixelAt(image, x, y).x < 0.5 * kEmission.r && count.leaks++ == 0)
                count.first = std::to_string(x) + "," + std::to_string(y);
        }
    }
    return count;
}

/// The closed mesh, its front half and the mesh as a solid in CSG, seen by `camera`: 0 leaks
/// in any.
void checkWatertight(const Mesh& mesh, const scene::CameraDesc& camera, const std::string& name) {
    std::vector<HalfSpace> solid = solidOf(mesh);
    std::string summary;
    for (int view = 0; view < 3; ++view) {
        const bool front = view == 1;
        const Mesh drawn = front ? frontHalf(mesh, camera.position) : view == 2 ? outwardWound(mesh) : mesh;
        std::string what = name + (front ? ", front half" : view == 0 ? ", closed" : ", a solid in CSG");
        LeakCount c = countLeaks(drawn, solid, camera, "watertight",
                                 view == 2 ? Drawn::Solid : Drawn::Triangles);
        INFO(what << ": " << c.leaks << " background pixels (first at " << c.first << ") of "
                  << c.inside << " inside the silhouette; 0 allowed");
        CHECK(c.leaks == 0);
        CHECK(c.inside > kWidth * kHeight / 5);
        summary += what + ": " + std::to_string(c.leaks) + " leaks in " + std::to_string(c.inside) +
                   " pixels\n";
    }
    WARN(summary);
}

scene::CameraDesc looking(DVec3 from, double fov, DVec3 up = {0, 1, 0}) {
    scene::CameraDesc c = test::lookAt(from, DVec3(0.0), fov);
    c.up = up;
    return c;
}

/// Faces the cube's z = −1 face from (0, 0, −4) with the pixel pitch there half the grid step:
/// pixel (i, j) meets the face at ((i − 48)·step/2, (36 − j)·step/2) (spec §6's camera).
scene::CameraDesc gridAligned(int cells) {
    double pitch = 1.0 / cells, distance = 3;
    double tanHalf = pitch * kHeight / (2 * distance);
    return looking({0, 0, -4}, 2 * std::atan(tanHalf) * 180 / test::kTestPi);
}

constexpr int kCubeCells = 36; // the face fills the image's height at two pixels per cell

} // namespace

TEST_CASE("A tessellated sphere seen at its pole has no holes", "[stress][watertight]") {
    // Straight down the y axis: the middle ray passes through both poles, where 32 triangles
    // meet. `up` is +z, since the default +y is parallel to the view.
    checkWatertight(uvSphere(16, 32), looking({0, 3.5, 0}, 40, {0, 0, 1}), "sphere at its pole");
}

TEST_CASE("A tessellated sphere seen along its equator has no holes", "[stress][watertight]") {
    // The middle row of rays lies in the plane y = 0 of the equator's edges, the middle column
    // in the plane x = 0 of the meridian facing the camera.
    checkWatertight(uvSphere(16, 32), looking({0, 0, -3.5}, 40), "sphere along its equator");
}

TEST_CASE("A gridded cube seen at a corner has no holes", "[stress][watertight]") {
    // The middle ray passes through two opposite corners, the middle column through the edges
    // x = z = ±1.
    checkWatertight(gridCube(kCubeCells), looking({3, 3, 3}, 45), "cube at a corner");
}

TEST_CASE("A gridded cube faced with pixel centres on its grid has no holes",
          "[stress][watertight]") {
    checkWatertight(gridCube(kCubeCells), gridAligned(kCubeCells), "cube on its grid");
}

TEST_CASE("The watertightness check sees hairline cracks", "[stress][watertight]") {
    // The control: the grid-aligned cube's front face as a soup of triangles shrunk by 1e-9
    // leaks along every edge, so the views above do put rays on the edges.
    Mesh mesh = gridCube(kCubeCells);
    scene::CameraDesc camera = gridAligned(kCubeCells);
    LeakCount c = countLeaks(cracked(frontHalf(mesh, camera.position), 1e-9), solidOf(mesh), camera,
                             "cracked");
    INFO(c.leaks << " background pixels of " << c.inside << " inside the silhouette");
    CHECK(c.leaks > c.inside / 2);
}
