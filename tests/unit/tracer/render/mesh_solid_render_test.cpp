// A closed mesh is a solid with an inside: a glass slab made of twelve triangles refracts a
// stripe pattern as a glass Box does, whichever way its triangles are wound; the same
// triangles with one face turned are no solid, and the picture shows it.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "scene/mesh_closure.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kWidth = 96, kHeight = 72;

/// The box from lo to hi as twelve triangles, counter-clockwise seen from outside unless
/// `inward`; `turnOne` turns the first one.
std::shared_ptr<const scene::MeshData> boxMesh(DVec3 lo, DVec3 hi, bool inward, bool turnOne) {
    auto mesh = std::make_shared<scene::MeshData>();
    for (int i = 0; i < 8; ++i)
        mesh->positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (int f = 0; f < 12; ++f) {
        int a = faces[f][0], b = faces[f][1], c = faces[f][2];
        if (inward != (turnOne && f == 0)) std::swap(b, c);
        mesh->triangles.push_back({{a, b, c}, {-1, -1, -1}, {-1, -1, -1}});
    }
    scene::markClosure(*mesh);
    return mesh;
}

/// A glass slab (from `slab`) before a striped wall, seen obliquely so that the stripes
/// are shifted by the refraction.
PixelBuffer renderSlab(const std::function<int32_t(SceneMaker&, int32_t)>& slab) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, lookAt({-1.5, 0.3, -5}, {0.5, 0, 2}, 30));
    m.desc.settings.ambient = scene::Color{1, 1, 1, 1};
    ShadingMaterial glass;
    glass.color = scene::Color{1, 1, 1, 1};
    glass.transparency = 1;
    glass.diffuse = 0;
    glass.ior = 1.5;
    m.draw(slab(m, m.material(glass)));
    scene::TextureDesc stripes;
    stripes.kind = scene::TextureKind::Stripes;
    stripes.colors = {{0, {1, 1, 0, 1}}, {1, {0, 0.2, 1, 1}}};
    stripes.size = 0.25;
    stripes.axis = {1, 0, 0};
    m.desc.textures.push_back(stripes);
    ShadingMaterial wall;
    wall.texture = 0;
    m.draw(m.plane({0, 0, -1}, {0, 0, 3}, m.material(wall)));
    return renderOk(m.desc);
}

/// Pixels differing by more than 1e-4 in any channel.
int differing(const PixelBuffer& a, const PixelBuffer& b) {
    int count = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            count += maxDifference(pixelAt(a, x, y), pixelAt(b, x, y)) > 1e-4;
    return count;
}

} // namespace

TEST_CASE("A closed mesh refracts as the solid it bounds", "[render][mesh]") {
    const DVec3 lo(-20, -20, 0), hi(20, 20, 1);
    const PixelBuffer box =
        renderSlab([&](SceneMaker& m, int32_t glass) { return m.box(lo, hi, glass); });
    auto meshSlab = [&](bool inward, bool turnOne) {
        return renderSlab([&](SceneMaker& m, int32_t glass) {
            m.desc.writtenMeshes.push_back(boxMesh(lo, hi, inward, turnOne));
            scene::MeshShape shape;
            shape.written = static_cast<int32_t>(m.desc.writtenMeshes.size() - 1);
            return m.entity(shape, glass, m.desc.writtenMeshes.back()->closed);
        });
    };
    // Triangles and box faces round differently: a stripe's edge may move by a pixel.
    const int allowed = kWidth * kHeight / 100;
    CHECK(differing(meshSlab(false, false), box) <= allowed);
    CHECK(differing(meshSlab(true, false), box) <= allowed);
    // One face turned: open, a surface without an inside, so rays are not bent back out.
    CHECK(differing(meshSlab(false, true), box) > kWidth * kHeight / 4);
}
