// Long runs of simple shapes drawn at the top level are made on the build's threads: the
// render scene must be the one drawing them one by one makes, whatever the thread count.
#include "scene_builder_util.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// Draws `count` spheres along a diagonal, every third with a material of its own.
void drawSpheres(SceneMaker& m, int count, int32_t material) {
    for (int i = 0; i < count; ++i) {
        const double at = i * 0.01;
        m.draw(m.sphere({at, 0.5 * at, -at}, 0.004 + (i % 7) * 0.0005, i % 3 == 0 ? material : -1));
    }
}

/// Runs of plain spheres (long ones, made apart, and a short one) between roots that are
/// not plain: a moved sphere, a sphere hidden from shadows, a difference, a plane.
scene::SceneDesc mixedScene() {
    SceneMaker m;
    const int32_t red = m.colored(1, 0, 0), blue = m.colored(0, 0, 1);
    drawSpheres(m, 20000, red);
    m.draw(m.transformed(m.sphere({0, 0, 0}, 1), {translate({0, 5, 0})}, blue));
    const int32_t hidden = m.sphere({0, -5, 0}, 1);
    m.desc.entities[static_cast<size_t>(hidden)].hidden = scene::kHiddenFromShadows;
    m.draw(hidden);
    drawSpheres(m, 5, red);
    m.draw(m.csg(scene::CsgOp::Difference, m.box({-1, -1, -1}, {1, 1, 1}), m.sphere({1, 1, 1}, 0.5)));
    m.draw(m.plane({0, 1, 0}, {0, -10, 0}));
    drawSpheres(m, 9000, blue); // last: after a hidden one, the hidden bits must reach its end
    return m.desc;
}

/// The same scene with every sphere drawn at the top level below a transform that does not
/// move it, which the build draws one root at a time.
scene::SceneDesc wrapSpheres(scene::SceneDesc desc) {
    for (int32_t& root : desc.drawn) {
        const scene::EntityDesc& e = desc.entities[static_cast<size_t>(root)];
        if (!std::holds_alternative<scene::SphereShape>(e.shape) || e.hidden != 0) continue;
        scene::EntityDesc wrapper;
        wrapper.shape = scene::TransformNode{root, {}};
        desc.entities.push_back(std::move(wrapper));
        root = static_cast<int32_t>(desc.entities.size() - 1);
    }
    return desc;
}

std::unique_ptr<RenderScene> build(const scene::SceneDesc& desc, unsigned threads) {
    std::string error;
    auto scene = buildRenderScene(desc, error, threads);
    REQUIRE(scene);
    return scene;
}

void requireSameScene(const RenderScene& a, const RenderScene& b) {
    REQUIRE(a.primitives.size() == b.primitives.size());
    for (size_t i = 0; i < a.primitives.size(); ++i) {
        INFO("primitive " << i);
        REQUIRE(a.primitives[i].material == b.primitives[i].material);
        REQUIRE(a.primitives[i].transform == b.primitives[i].transform);
        REQUIRE(a.primitives[i].geometry.index() == b.primitives[i].geometry.index());
        const Bounds3 boundsA = geometryBounds(a.primitives[i].geometry);
        const Bounds3 boundsB = geometryBounds(b.primitives[i].geometry);
        REQUIRE(boundsA.lo == boundsB.lo);
        REQUIRE(boundsA.hi == boundsB.hi);
    }
    CHECK((a.primitiveEntities == b.primitiveEntities));
    CHECK((a.hiddenPrimitives == b.hiddenPrimitives));
    CHECK(a.transforms.size() == b.transforms.size());
    CHECK(a.csgNodes.size() == b.csgNodes.size());
    CHECK(a.planes.size() == b.planes.size());
    CHECK(a.bvh.nodeCount() == b.bvh.nodeCount());
    CHECK(a.bvh.depth() == b.bvh.depth());
    CHECK(a.byteSize() == b.byteSize());
}

} // namespace

TEST_CASE("Runs of plain roots build the scene drawing them one by one builds", "[scene-build]") {
    const scene::SceneDesc plain = mixedScene();
    const auto oneByOne = build(wrapSpheres(plain), 1);
    REQUIRE(oneByOne->primitives.size() == 29000 + 1 + 1 + 2 + 1 + 5);
    REQUIRE(oneByOne->hiddenPrimitives.size() == oneByOne->primitives.size());
    for (unsigned threads : {1u, 2u, 3u}) {
        INFO(threads << " threads");
        requireSameScene(*build(plain, threads), *oneByOne);
    }
}
