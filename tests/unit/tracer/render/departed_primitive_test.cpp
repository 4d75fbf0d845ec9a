// A ray spawned at a surface skips the primitive it leaves only where it could not meet it again.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"
#include "tracer/sampling.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using crt::tracer::test::SceneMaker;
using crt::tracer::test::scale;
using crt::tracer::test::translate;

namespace {

/// Shapes of every kind the rule distinguishes: convex solids (a sphere, an ellipsoid, a box,
/// a closed cylinder), flat ones (a disc, a quad, a triangle), ones a ray can leave and meet
/// again (a torus, an open cylinder), and a mesh folded so that a ray leaving one face can meet
/// the other (only the face it leaves is skipped).
std::unique_ptr<RenderScene> shapes() {
    SceneMaker maker;
    maker.draw(maker.sphere({-4, 0, 0}, 1));
    maker.draw(maker.transformed(maker.sphere({0, 0, 0}, 1), {scale({2, 0.5, 1}), translate({0, 0, 4})}));
    maker.draw(maker.box({3, -1, -1}, {5, 1, 1}));
    maker.draw(maker.entity(crt::scene::CylinderShape{{0, -1, -4}, {0, 1, -4}, 1, false}));
    maker.draw(maker.entity(crt::scene::CylinderShape{{-4, -1, 4}, {-4, 1, 4}, 1, true}, -1, false));
    maker.draw(maker.entity(crt::scene::TorusShape{{4, 0, 4}, 1.2, 0.4, {0, 1, 0.3}}));
    maker.draw(maker.entity(crt::scene::DiscShape{{4, 0, -4}, {0.3, 1, 0}, 1, 0.2}, -1, false));
    maker.draw(maker.entity(crt::scene::QuadShape{{-5, 0, -5}, {2, 0.5, 0}, {0, 0.5, 2}}, -1, false));
    maker.draw(maker.entity(crt::scene::TriangleShape{{-1, -1, -1}, {1, -1, -1}, {0, 1, 1}}, -1, false));
    auto fold = std::make_shared<crt::scene::MeshData>();
    fold->positions = {{-1, -1, -6}, {1, -1, -6}, {0, 1, -7}, {0, 1, -5}};
    fold->triangles = {{{0, 1, 2}, {-1, -1, -1}, {-1, -1, -1}}, {{1, 0, 3}, {-1, -1, -1}, {-1, -1, -1}}};
    maker.desc.writtenMeshes.push_back(fold);
    crt::scene::MeshShape mesh;
    mesh.written = 0;
    maker.draw(maker.entity(mesh, -1, false));
    std::string error;
    auto scene = buildRenderScene(maker.desc, error);
    REQUIRE(scene);
    return scene;
}

Vec3 randomDirection(SampleRng& rng) {
    for (;;) {
        Vec3 v(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
        double length = glm::length(v);
        if (length > 0.1 && length <= 1) return v / length;
    }
}

} // namespace

TEST_CASE("A ray skips the primitive it leaves only when it cannot meet it again", "[render]") {
    auto scene = shapes();
    QueryScratch scratch;
    RayStats stats;
    SampleRng rng(7, 0, 0);
    int skipped = 0, tested = 0, enteringSolids = 0, meshFaces = 0;
    for (int i = 0; i < 4000; ++i) {
        // A point on some surface, seen from outside the group of shapes.
        Ray camera{12.0 * randomDirection(rng), Vec3(0)};
        camera.dir = glm::normalize(Vec3(rng.uniform() * 8 - 4, rng.uniform() * 2 - 1, rng.uniform() * 8 - 4) - camera.origin);
        Hit hit;
        if (!scene->intersect(camera, kInfinity, hit, scratch, stats)) continue;
        const SurfaceInteraction si = scene->interaction(camera, hit);
        // Rays from it every way, off the surface to the side each goes, as the integrator
        // spawns them.
        for (int j = 0; j < 8; ++j) {
            const Vec3 dir = randomDirection(rng);
            const Ray ray{offsetRayOrigin(si.point, si.pointError, si.normal, dir), dir};
            const Departure departed = scene->departedPrimitive(hit, si, dir);
            const Geometry& geometry = scene->primitives[hit.primitive].geometry;
            if (isBoundedConvex(geometry) && glm::dot(dir, si.normal) < 0) {
                ++enteringSolids;
                CHECK(departed.primitive == -1);
            }
            if (departed.primitive < 0) {
                ++tested;
                continue;
            }
            ++skipped;
            CHECK(departed.primitive == hit.primitive);
            const bool mesh = holds<MeshGeometry>(geometry);
            if (mesh) {
                ++meshFaces;
                CHECK(departed.part == hit.crossing.part);
            } else {
                CHECK(departed.part == kNoPart);
            }
            // What the queries would have found on it: nothing.
            scene->forEachCrossing(ray, kInfinity, {}, scratch, stats, [&](const Hit& hit) {
                if (hit.primitive == departed.primitive && (departed.part == kNoPart || hit.crossing.part == departed.part)) {
                    FAIL("a ray meets the face it left at t = " << hit.t);
                }
                return true;
            });
            Hit skippedHit, fullHit;
            const bool skippedFound = scene->intersect(ray, kInfinity, skippedHit, scratch, stats, departed);
            const bool fullFound = scene->intersect(ray, kInfinity, fullHit, scratch, stats);
            REQUIRE(skippedFound == fullFound);
            if (fullFound) CHECK((skippedHit.t == fullHit.t && skippedHit.primitive == fullHit.primitive));
        }
    }
    // Each case came up often enough to mean something.
    CHECK(skipped > 2000);
    CHECK(tested > 2000);
    CHECK(enteringSolids > 500);
    CHECK(meshFaces > 100);
}

TEST_CASE("A torus or an open cylinder is never skipped: a ray leaving it may meet it again", "[render]") {
    auto scene = shapes();
    for (size_t p = 0; p < scene->primitives.size(); ++p) {
        const Geometry& geometry = scene->primitives[p].geometry;
        const bool torus = holds<TorusGeometry>(geometry);
        const bool open = holds<CylinderGeometry>(geometry) && !isSolid(geometry);
        if (!torus && !open) continue;
        Hit hit{1.0, static_cast<int32_t>(p), Crossing{1.0, 0}, false};
        SurfaceInteraction si;
        si.normal = Vec3(0, 0, 1);
        CHECK(scene->departedPrimitive(hit, si, Vec3(0, 0, 1)).primitive == -1);
        CHECK(scene->departedPrimitive(hit, si, Vec3(0, 0, -1)).primitive == -1);
    }
}
