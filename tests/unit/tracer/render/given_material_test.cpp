// Materials given by transforms (`<material m>`): to the parts that have none, the nearest
// giver's, through CSG, groups and meshes alike.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// The material of each primitive, in the order the builder made them.
std::vector<int32_t> primitiveMaterials(const scene::SceneDesc& desc) {
    std::string error;
    std::unique_ptr<RenderScene> built = buildRenderScene(desc, error);
    REQUIRE(built);
    std::vector<int32_t> materials;
    for (const Primitive& p : built->primitives) materials.push_back(p.material);
    return materials;
}

} // namespace

TEST_CASE("A part without a material is drawn with the default one", "[material]") {
    SceneMaker maker;
    const int32_t red = maker.colored(1, 0, 0);
    maker.draw(maker.sphere(Vec3(0), 1));
    maker.draw(maker.sphere(Vec3(3, 0, 0), 1, red));
    const int32_t defaultMaterial = static_cast<int32_t>(maker.desc.materials.size());
    CHECK(primitiveMaterials(maker.desc) == std::vector<int32_t>{defaultMaterial, red});
}

TEST_CASE("A transform's material goes to the parts that have none; parts keep their own",
          "[material]") {
    SceneMaker maker;
    const int32_t red = maker.colored(1, 0, 0), blue = maker.colored(0, 0, 1),
                  green = maker.colored(0, 1, 0);
    const int32_t bare = maker.sphere(Vec3(0), 1);
    const int32_t own = maker.box(Vec3(2, 0, 0), Vec3(3, 1, 1), blue);
    const int32_t cut = maker.csg(scene::CsgOp::Difference, bare, own);
    maker.draw(maker.transformed(cut, {translate(Vec3(0, 5, 0))}, red));
    // Nested givers: the nearer one wins, the outer one reaches only what is still bare.
    const int32_t inner = maker.transformed(maker.sphere(Vec3(0), 1), {}, green);
    maker.draw(maker.transformed(
        maker.csg(scene::CsgOp::Union, inner, maker.sphere(Vec3(5, 0, 0), 1)), {}, red));
    // The same entity drawn bare elsewhere keeps the default material.
    maker.draw(bare);
    const int32_t defaultMaterial = static_cast<int32_t>(maker.desc.materials.size());
    CHECK(primitiveMaterials(maker.desc) ==
          std::vector<int32_t>{red, blue, green, red, defaultMaterial});
}
