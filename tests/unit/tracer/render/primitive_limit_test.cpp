// What a scene stores, counted from its description by the rule the renderer builds by
// (scene/instancing.hpp): the renderer refuses a description that would store more than
// RenderLimits::maxPrimitives before expanding it, whoever built the description (the front
// end refuses such scripts already).
#include "scene_builder_util.hpp"
#include "scene/instancing.hpp"
#include "tracer/render_scene.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// A sphere united with itself `doublings` times: doublings + 1 entities, 2^doublings primitives.
int32_t doubled(SceneMaker& m, int doublings) {
    int32_t g = m.sphere(Vec3(0), 1);
    for (int i = 0; i < doublings; ++i) g = m.csg(scene::CsgOp::Union, g, g);
    return g;
}

} // namespace

TEST_CASE("what a scene stores is counted as the renderer stores it", "[limits]") {
    SceneMaker m;
    int32_t g = doubled(m, 10); // drawn three times below: stored once, each drawing an instance
    int32_t moved = m.transformed(g, {translate(glm::dvec3(1, 0, 0))});
    m.draw(m.entity(scene::GroupNode{{g, moved, m.sphere(Vec3(3), 1)}}));
    m.draw(moved);
    const scene::SceneStorage storage = scene::storageOf(m.desc);
    CHECK(storage.instanced[static_cast<size_t>(g)]);
    CHECK_FALSE(storage.instanced[static_cast<size_t>(moved)]); // a transform: its child repeats
    CHECK(storage.storedAfter == std::vector<uint64_t>{1024 + 3, 1024 + 4});
    CHECK(storage.copied == 1); // the sphere; the rest are 3 instances and the prototype
    CHECK(storage.instances == 3);
    std::string error;
    auto built = buildRenderScene(m.desc, error);
    REQUIRE(built);
    CHECK(built->storedPrimitives() == storage.stored());
}

TEST_CASE("a group drawing a shared entity 10,000 times stores it once", "[limits]") {
    SceneMaker m;
    const int32_t tree = doubled(m, 10);
    scene::GroupNode forest;
    for (int i = 0; i < 10000; ++i) forest.members.push_back(m.transformed(tree, {translate(glm::dvec3(i, 0, 0))}));
    const int32_t drawn = m.entity(forest);
    m.draw(drawn);
    CHECK(scene::storageOf(m.desc).stored() == 1024 + 10000);
    std::string error;
    auto built = buildRenderScene(m.desc, error); // within the default limit, though it expands to 10 M
    REQUIRE(built);
    CHECK(built->storedPrimitives() == 1024 + 10000);

    // Drawn twice, the forest itself is the shared entity, and instances are one level deep:
    // its prototype holds its 10,240,000 primitives, past the limit.
    m.draw(drawn);
    CHECK(scene::storageOf(m.desc).stored() == 10240000 + 2);
    CHECK_FALSE(buildRenderScene(m.desc, error));
}

TEST_CASE("the primitive count saturates instead of overflowing", "[limits]") {
    SceneMaker m;
    m.draw(doubled(m, 70));
    CHECK(scene::storageOf(m.desc).stored() == std::numeric_limits<uint64_t>::max());
}

TEST_CASE("a scene past maxPrimitives is refused before it is expanded", "[limits]") {
    SceneMaker m;
    m.draw(doubled(m, 40)); // 2^40 primitives: expanding them would take terabytes
    std::string error;
    CHECK_FALSE(buildRenderScene(m.desc, error));
    CHECK(error == "the scene stores more than 5000000 primitives; raise the limit with --max-primitives");

    SceneMaker small;
    small.draw(doubled(small, 3));
    small.desc.limits.maxPrimitives = 8;
    CHECK(buildRenderScene(small.desc, error));
    small.desc.limits.maxPrimitives = 7;
    CHECK_FALSE(buildRenderScene(small.desc, error));
}
