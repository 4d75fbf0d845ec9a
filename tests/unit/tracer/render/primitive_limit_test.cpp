// The renderer refuses a description whose expansion passes RenderLimits::maxPrimitives before
// expanding it, whoever built the description (the front end refuses such scripts already).
#include "scene_builder_util.hpp"
#include "scene/primitive_count.hpp"
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

TEST_CASE("primitives are counted through shared CSG operands, groups and transforms", "[limits]") {
    SceneMaker m;
    int32_t g = doubled(m, 10);
    int32_t moved = m.transformed(g, {translate(glm::dvec3(1, 0, 0))});
    m.draw(m.entity(scene::GroupNode{{g, moved, m.sphere(Vec3(3), 1)}}));
    m.draw(moved);
    CHECK(scene::drawnPrimitives(m.desc) == 1024 + 1024 + 1 + 1024);
}

TEST_CASE("the primitive count saturates instead of overflowing", "[limits]") {
    SceneMaker m;
    m.draw(doubled(m, 70));
    CHECK(scene::drawnPrimitives(m.desc) == std::numeric_limits<uint64_t>::max());
}

TEST_CASE("a scene past maxPrimitives is refused before it is expanded", "[limits]") {
    SceneMaker m;
    m.draw(doubled(m, 40)); // 2^40 primitives: expanding them would take terabytes
    std::string error;
    CHECK_FALSE(buildRenderScene(m.desc, error));
    CHECK(error == "the scene expands to more than 5000000 primitives; raise the limit with --max-primitives");

    SceneMaker small;
    small.draw(doubled(small, 3));
    small.desc.limits.maxPrimitives = 8;
    CHECK(buildRenderScene(small.desc, error));
    small.desc.limits.maxPrimitives = 7;
    CHECK_FALSE(buildRenderScene(small.desc, error));
}
