// Modifiers: POV-Ray's left-handed rotations, order of application, normals under scale.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"
#include "tracer/transform.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace crt::tracer;
using namespace crt::tracer::test;
namespace scene = crt::scene;

namespace {

void requireNear(const Vec3& a, const Vec3& b) {
    INFO("got (" << a.x << ", " << a.y << ", " << a.z << ") expected (" << b.x << ", " << b.y << ", " << b.z << ")");
    REQUIRE(glm::length(a - b) < 1e-12);
}

} // namespace

TEST_CASE("Rotations follow the spec's left-handed convention", "[transform]") {
    requireNear(Transform::fromModifiers({rotate(Vec3(0, 90, 0))}).point(Vec3(1, 0, 0)), Vec3(0, 0, -1));
    requireNear(Transform::fromModifiers({rotate(Vec3(90, 0, 0))}).point(Vec3(0, 1, 0)), Vec3(0, 0, 1));
    requireNear(Transform::fromModifiers({rotate(Vec3(0, 0, 90))}).point(Vec3(1, 0, 0)), Vec3(0, 1, 0));
    // x first, then y: (0,1,0) -x90-> (0,0,1) -y90-> (1,0,0)
    requireNear(Transform::fromModifiers({rotate(Vec3(90, 90, 0))}).point(Vec3(0, 1, 0)), Vec3(1, 0, 0));
}

TEST_CASE("Modifiers apply left to right about the world origin", "[transform]") {
    Transform a = Transform::fromModifiers({translate(Vec3(1, 0, 0)), rotate(Vec3(0, 0, 90))});
    requireNear(a.point(Vec3(0)), Vec3(0, 1, 0));
    Transform b = Transform::fromModifiers({rotate(Vec3(0, 0, 90)), translate(Vec3(1, 0, 0))});
    requireNear(b.point(Vec3(0)), Vec3(1, 0, 0));
    Transform s = Transform::fromModifiers({scale(Vec3(2, 3, 4)), translate(Vec3(1, 1, 1))});
    requireNear(s.point(Vec3(1)), Vec3(3, 4, 5));
    requireNear(s.inverse().point(Vec3(3, 4, 5)), Vec3(1));
}

TEST_CASE("Normals stay perpendicular under non-uniform scale", "[transform]") {
    SceneMaker m;
    // An ellipsoid: the unit sphere scaled by (2, 1, 1).
    m.draw(m.transformed(m.sphere(Vec3(0), 1), {scale(Vec3(2, 1, 1))}));
    std::string error;
    auto scene = buildRenderScene(m.desc, error);
    REQUIRE(scene);
    QueryScratch scratch;
    RayStats stats;
    for (double x : {-1.5, -0.7, 0.0, 0.9, 1.6}) {
        Ray ray{Vec3(x, 5, 0.1), Vec3(0, -1, 0)};
        Hit hit;
        REQUIRE(scene->intersect(ray, kInfinity, hit, scratch, stats));
        SurfaceInteraction si = scene->interaction(ray, hit);
        // The ellipsoid x²/4 + y² + z² = 1 has gradient (x/2, 2y, 2z).
        Vec3 p = si.point;
        REQUIRE(p.x * p.x / 4 + p.y * p.y + p.z * p.z == Approx(1).epsilon(1e-12));
        requireNear(si.normal, glm::normalize(Vec3(p.x / 2, 2 * p.y, 2 * p.z)));
        // The error bound is a real bound: the point is within it of the exact surface.
        double largest = std::max({si.pointError.x, si.pointError.y, si.pointError.z});
        CHECK(largest > 0);
        CHECK(largest < 1e-12);
    }
}

TEST_CASE("A matrix modifier maps x, y and z to its columns and adds its offset, in order with the "
          "others",
          "[transform]") {
    scene::Modifier shear{scene::ModifierKind::Matrix, Vec3(0.25, -0.1, 0)};
    shear.linear = glm::dmat3(Vec3(1, 0.4, 0), Vec3(0.6, 1, 0), Vec3(0, 0, 1));
    const Transform t = Transform::fromModifiers({shear});
    requireNear(t.point(Vec3(1, 0, 0)), Vec3(1.25, 0.3, 0));
    requireNear(t.point(Vec3(0, 1, 0)), Vec3(0.85, 0.9, 0));
    requireNear(t.inverse().point(t.point(Vec3(0.3, -2, 5))), Vec3(0.3, -2, 5));
    // After a translation: the matrix moves the translated point.
    requireNear(Transform::fromModifiers({translate(Vec3(0, 1, 0)), shear}).point(Vec3(0)),
                Vec3(0.85, 0.9, 0));
}
