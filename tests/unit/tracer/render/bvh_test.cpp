// The BVH finds exactly what a brute-force search over every primitive finds.
#include "scene_builder_util.hpp"
#include "tracer/render_scene.hpp"
#include "tracer/sampling.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using crt::tracer::test::SceneMaker;

namespace {

/// Nearest crossing with t > 0 over all primitives, without the BVH.
double bruteForce(const RenderScene& scene, const Ray& ray) {
    double best = kInfinity;
    for (const Primitive& p : scene.primitives) {
        CrossingList list;
        Ray r = p.transform < 0 ? ray : scene.transforms[p.transform].toObject.ray(ray);
        crossLine(p.geometry, r, list);
        for (int i = 0; i < list.count; ++i)
            if (list[i].t > 0 && list[i].t < best) best = list[i].t;
    }
    return best;
}

/// The nearest hit through the BVH, required to equal brute force's; whether there is one.
bool nearestAgrees(const RenderScene& scene, const Ray& ray, QueryScratch& scratch, RayStats& stats) {
    Hit hit;
    bool found = scene.intersect(ray, kInfinity, hit, scratch, stats);
    double expected = bruteForce(scene, ray);
    REQUIRE(found == (expected < kInfinity));
    if (found) REQUIRE(hit.t == expected);
    return found;
}

std::unique_ptr<RenderScene> buildWithBvh(const SceneMaker& maker) {
    std::string error;
    auto scene = buildRenderScene(maker.desc, error);
    REQUIRE(scene);
    REQUIRE(scene->bvh.nodeCount() > 1);
    return scene;
}

} // namespace

TEST_CASE("BVH nearest hits equal brute force on random sphere scenes", "[bvh]") {
    for (uint64_t seed : {1u, 2u, 3u}) {
        SceneMaker maker;
        SampleRng rng(seed, 0, 0);
        int count = seed == 3 ? 2000 : 300;
        for (int i = 0; i < count; ++i) {
            Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
            maker.draw(maker.sphere(c, 0.05 + rng.uniform() * 0.8));
        }
        // Some transformed boxes too, so world bounds of rotated objects are exercised.
        for (int i = 0; i < 50; ++i) {
            Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
            int32_t b = maker.box(Vec3(-0.3), Vec3(0.3));
            maker.draw(maker.transformed(b, {crt::tracer::test::rotate(Vec3(rng.uniform() * 90, rng.uniform() * 90, 0)),
                                             crt::tracer::test::translate(c)}));
        }
        auto scene = buildWithBvh(maker);
        QueryScratch scratch;
        RayStats stats;
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            Ray ray{Vec3(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 30 - 15),
                    glm::normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5))};
            hits += nearestAgrees(*scene, ray, scratch, stats);
        }
        CHECK(hits > 300);
        // The BVH must prune: far fewer tests than primitives × rays.
        CHECK(stats.intersectionTests < 3000ull * scene->primitives.size() / 10);
    }
}

TEST_CASE("BVH: every crossing query agrees with brute force counts", "[bvh]") {
    SceneMaker maker;
    SampleRng rng(7, 0, 0);
    for (int i = 0; i < 400; ++i)
        maker.draw(maker.sphere(Vec3(rng.uniform() * 10, rng.uniform() * 10, rng.uniform() * 10), 0.3));
    maker.draw(maker.plane(Vec3(0, 1, 0), Vec3(0, -1, 0)));
    std::string error;
    auto scene = buildRenderScene(maker.desc, error);
    REQUIRE(scene);
    CHECK(scene->planes.size() == 1);
    QueryScratch scratch;
    RayStats stats;
    for (int i = 0; i < 500; ++i) {
        Ray ray{Vec3(rng.uniform() * 10, 12, rng.uniform() * 10), glm::normalize(Vec3(rng.uniform() - 0.5, -1, rng.uniform() - 0.5))};
        int counted = 0;
        scene->forEachCrossing(ray, kInfinity, {}, scratch, stats, [&](const Hit&) {
            ++counted;
            return true;
        });
        int expected = 0;
        for (const Primitive& p : scene->primitives) {
            CrossingList list;
            crossLine(p.geometry, ray, list);
            for (int k = 0; k < list.count; ++k) expected += list[k].t > 0;
        }
        REQUIRE(counted == expected);
    }
}

TEST_CASE("BVH float boxes miss nothing: far from the origin, in face planes, axis-parallel", "[bvh]") {
    // The wide BVH tests float boxes against a float copy of the ray; these rays sit where
    // that rounding matters. Each must find exactly what brute force finds.
    SceneMaker maker;
    const Vec3 far(1.0e5, -2.5e5, 3.0e5);
    SampleRng rng(11, 0, 0);
    std::vector<Vec3> centres;
    for (int i = 0; i < 200; ++i) {
        Vec3 c = far + Vec3(rng.uniform() * 4, rng.uniform() * 4, rng.uniform() * 4);
        centres.push_back(c);
        maker.draw(maker.sphere(c, 1.0e-3));
    }
    // Unit boxes on a grid: rays along their faces lie exactly in the boxes' face planes.
    for (int x = 0; x < 6; ++x)
        for (int z = 0; z < 6; ++z) maker.draw(maker.box(Vec3(2 * x, 0, 2 * z), Vec3(2 * x + 1, 1, 2 * z + 1)));
    auto scene = buildWithBvh(maker);
    QueryScratch scratch;
    RayStats stats;
    auto agree = [&](const Ray& ray) { return nearestAgrees(*scene, ray, scratch, stats); };
    int hits = 0;
    // Through each small sphere's centre, from a point near the world origin and from
    // nearby; a tiny sphere far away is where a float origin or box could lose it.
    for (const Vec3& c : centres) {
        hits += agree(Ray{Vec3(0.5, 0.25, -0.75), glm::normalize(c - Vec3(0.5, 0.25, -0.75))});
        Vec3 from = c + Vec3(3, -2, 1);
        hits += agree(Ray{from, glm::normalize(c - from)});
    }
    CHECK(hits == 2 * int(centres.size()));
    // In the planes y = 0 and y = 1 (the boxes' bottom and top faces) and x = 2k or 2k + 1
    // (their sides), axis-parallel: zero direction components give infinite reciprocals.
    int grazing = 0;
    for (double y : {0.0, 1.0, 0.5})
        for (int k = 0; k < 6; ++k)
            for (double x : {2.0 * k, 2.0 * k + 1, 2.0 * k + 0.5}) {
                grazing += agree(Ray{Vec3(x, y, -5), Vec3(0, 0, 1)});
                grazing += agree(Ray{Vec3(-5, y, x), Vec3(1, 0, 0)});
                grazing += agree(Ray{Vec3(x, 5, x), Vec3(0, -1, 0)});
            }
    CHECK(grazing > 0);
}
