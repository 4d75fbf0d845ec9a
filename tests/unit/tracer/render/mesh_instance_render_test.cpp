// A mesh drawn many times is stored once, and the picture is the one its copies make: each
// drawing keeps its own transform, material, texture and bump, in CSG too. Its triangles
// count once against the primitive limit.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "scene/mesh_closure.hpp"
#include "tracer/render_scene.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kWidth = 96, kHeight = 64;

/// A bumpy square of 6 × 6 cells over [0, 0.75]², heights in 16ths (every coordinate exact),
/// with uvs, so textures and bumps have something to read.
std::shared_ptr<const scene::MeshData> hill() {
    auto mesh = std::make_shared<scene::MeshData>();
    constexpr int n = 7;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int h = (i * (n - 1 - i) + j * (n - 1 - j)) % 5;
            mesh->positions.push_back({i / 8.0, h / 16.0, j / 8.0});
            mesh->uvs.push_back({i / 6.0, j / 6.0});
        }
    }
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            mesh->triangles.push_back({{a, c, b}, {-1, -1, -1}, {a, c, b}});
            mesh->triangles.push_back({{b, c, d}, {-1, -1, -1}, {b, c, d}});
        }
    }
    return mesh;
}

/// An octahedron of radius 0.25 about (0.25, 0.25, 0.25): a closed mesh, for CSG.
std::shared_ptr<const scene::MeshData> octahedron() {
    auto mesh = std::make_shared<scene::MeshData>();
    const double c = 0.25;
    mesh->positions = {{c + c, c, c}, {0, c, c}, {c, c + c, c}, {c, 0, c}, {c, c, c + c}, {c, c, 0}};
    const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (const auto& f : faces) mesh->triangles.push_back({{f[0], f[1], f[2]}, {-1, -1, -1}, {-1, -1, -1}});
    scene::markClosure(*mesh);
    return mesh;
}

/// Each mesh drawing's own data (copied) or one data for all (shared).
enum class Storage { Shared, Copied };

/// The written mesh `data`, shared with the drawings before or copied for this one.
int32_t meshEntity(SceneMaker& m, const std::shared_ptr<const scene::MeshData>& data, Storage storage) {
    auto& meshes = m.desc.writtenMeshes;
    auto known = std::find(meshes.begin(), meshes.end(), data);
    if (storage == Storage::Copied || known == meshes.end()) {
        meshes.push_back(storage == Storage::Copied ? std::make_shared<scene::MeshData>(*data) : data);
        known = meshes.end() - 1;
    }
    scene::MeshShape shape;
    shape.written = static_cast<int32_t>(known - meshes.begin());
    return m.entity(shape, -1, data->closed);
}

/// The material of drawing (i, j): its own colour; every third textured by a checker in the
/// mesh's own space, and every fifth bumped.
int32_t materialOf(SceneMaker& m, int i, int j) {
    ShadingMaterial mat;
    mat.color = scene::Color{0.3 + 0.2 * i, 0.9 - 0.2 * j, 0.5, 1};
    mat.specular = 0.4;
    mat.shininess = 20;
    const int k = 4 * i + j;
    if (k % 3 == 0) {
        scene::TextureDesc checker;
        checker.size = 0.125;
        checker.colors = {{0, {1, 0.9, 0.2, 1}}, {1, {0.1, 0.2, 0.8, 1}}};
        m.desc.textures.push_back(checker);
        mat.texture = static_cast<int32_t>(m.desc.textures.size() - 1);
    }
    if (k % 5 == 0) {
        scene::TextureDesc bump;
        bump.kind = scene::TextureKind::NoiseBump;
        bump.size = 0.1;
        bump.strength = 0.8;
        m.desc.textures.push_back(bump);
        mat.bump = static_cast<int32_t>(m.desc.textures.size() - 1);
    }
    return m.material(mat);
}

/// 4 × 4 drawings of the hill, moved by whole units, each with its own material; and a box
/// with two octahedra cut out of it, which are one mesh drawn twice.
scene::SceneDesc field(Storage storage) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, lookAt({1.25, 2.5, -1.25}, {1.5, 0, 1.75}, 70));
    m.desc.settings.ambient = scene::Color{0.1, 0.1, 0.1, 1};
    m.desc.lights.push_back(parallelLight({-2, 3, -3}));
    const auto hillData = hill();
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const int32_t drawing = meshEntity(m, hillData, storage);
            m.draw(m.transformed(drawing, {translate({i, 0, j})}, materialOf(m, i, j)));
        }
    }
    const auto cutter = octahedron();
    const int32_t first = m.transformed(meshEntity(m, cutter, storage), {translate({-0.75, 0.5, 1})});
    const int32_t second = m.transformed(meshEntity(m, cutter, storage), {translate({-0.75, 0.5, 2})});
    const int32_t block = m.box({-0.875, 0, 0.75}, {-0.125, 0.875, 2.75}, m.colored(0.8, 0.8, 0.8));
    m.draw(m.csg(scene::CsgOp::Difference, block, m.csg(scene::CsgOp::Union, first, second)));
    return m.desc;
}

} // namespace

TEST_CASE("A mesh drawn many times is stored once and renders as its copies do", "[render][mesh]") {
    const scene::SceneDesc shared = field(Storage::Shared), copied = field(Storage::Copied);
    REQUIRE(shared.writtenMeshes.size() == 2);
    REQUIRE(copied.writtenMeshes.size() == 18);
    std::string error;
    const auto sharedScene = buildRenderScene(shared, error);
    const auto copiedScene = buildRenderScene(copied, error);
    REQUIRE(sharedScene);
    REQUIRE(copiedScene);
    CHECK(sharedScene->meshes.size() == 2);
    CHECK(copiedScene->meshes.size() == 18);
    // 16 + 2 drawings and a box; the triangles of one hill and one octahedron, or of each copy.
    const uint64_t hillTriangles = 72, octahedronTriangles = 8;
    CHECK(sharedScene->storedPrimitives() == 19 + hillTriangles + octahedronTriangles);
    CHECK(copiedScene->storedPrimitives() == 19 + 16 * hillTriangles + 2 * octahedronTriangles);
    CHECK(sharedScene->byteSize() < copiedScene->byteSize());

    const PixelBuffer a = renderOk(shared), b = renderOk(copied);
    CHECK(a.pixels == b.pixels);
    // The scene shows what it should: textured, bumped and plain drawings, and the block.
    int lit = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) lit += maxDifference(pixelAt(a, x, y), DVec3(0.0)) > 0.05;
    CHECK(lit > kWidth * kHeight / 5);
}

TEST_CASE("A drawing's texture and bump move with it", "[render][mesh]") {
    // One textured, bumped hill moved by (3, 0, 2) and seen from a camera moved alike looks
    // as the hill at its place does: the transform is exact, so to the bit.
    auto scene = [](DVec3 offset) {
        SceneMaker m;
        m.desc = blankScene(kWidth, kHeight, lookAt(DVec3(0.5, 1.5, -1) + offset, DVec3(0.375, 0, 0.375) + offset, 50));
        m.desc.lights.push_back(parallelLight(DVec3(-2, 3, -3) + offset, offset));
        m.desc.settings.ambient = scene::Color{0.1, 0.1, 0.1, 1};
        m.draw(m.transformed(meshEntity(m, hill(), Storage::Shared), {translate(offset)}, materialOf(m, 0, 0)));
        return m.desc;
    };
    const PixelBuffer home = renderOk(scene(DVec3(0.0))), moved = renderOk(scene({3, 0, 2}));
    CHECK(home.pixels == moved.pixels);
}

TEST_CASE("A mesh drawn 1,000 times counts its triangles once against the primitive limit", "[limits][mesh]") {
    SceneMaker m;
    const auto data = hill();
    for (int i = 0; i < 1000; ++i)
        m.draw(m.transformed(meshEntity(m, data, Storage::Shared), {translate({i, 0, 0})}));
    REQUIRE(m.desc.writtenMeshes.size() == 1);
    std::string error;
    m.desc.limits.maxPrimitives = 1000 + 72;
    const auto scene = buildRenderScene(m.desc, error);
    REQUIRE(scene);
    CHECK(scene->primitives.size() == 1000);
    CHECK(scene->storedPrimitives() == 1072);
    m.desc.limits.maxPrimitives = 1000 + 71;
    CHECK_FALSE(buildRenderScene(m.desc, error));
    CHECK(error == "the scene stores more than 1071 primitives with the 72 triangles of a Mesh; raise "
                   "the limit with --max-primitives");
}
