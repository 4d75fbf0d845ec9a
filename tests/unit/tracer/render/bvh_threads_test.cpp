// The BVH built on several threads is the tree built on one: every ray visits the same items
// in the same order, so renders cannot depend on the thread count.
#include "tracer/bvh.hpp"
#include "tracer/sampling.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;

namespace {

/// Boxes scattered in a cube, clustered in places (uneven splits), some of them long and
/// thin (overlapping bins), enough that the build hands subtrees to threads.
std::vector<Bounds3> scatteredBoxes(size_t count) {
    SampleRng rng(7, 0, 0);
    std::vector<Bounds3> boxes;
    boxes.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        const double spread = i % 3 == 0 ? 2 : 100;
        const Vec3 c(rng.uniform() * spread, rng.uniform() * spread, rng.uniform() * 100);
        const Vec3 half = i % 10 == 0 ? Vec3(5, 0.01, 0.01) : Vec3(0.05 + rng.uniform() * 0.5);
        Bounds3 b;
        b.include(c - half);
        b.include(c + half);
        boxes.push_back(b);
    }
    return boxes;
}

/// The items each ray's traversal visits, in order, over the whole segment.
template <typename Tree>
std::vector<std::vector<int32_t>> visits(const Tree& bvh, const std::vector<Ray>& rays) {
    std::vector<std::vector<int32_t>> result;
    RayStats stats;
    for (const Ray& ray : rays) {
        std::vector<int32_t>& seen = result.emplace_back();
        const double tMax = kInfinity;
        bvh.traverse(LazyBoxRay(ray), tMax, stats, [&](int32_t item) {
            seen.push_back(item);
            return true;
        });
    }
    return result;
}

} // namespace

TEMPLATE_TEST_CASE("the BVH is the same tree whatever the number of threads that build it", "[bvh]", WideBvh<4>,
                   WideBvh<8>) {
    const std::vector<Bounds3> boxes = scatteredBoxes(60000);
    std::vector<Ray> rays;
    SampleRng rng(11, 0, 0);
    for (int i = 0; i < 300; ++i) {
        const Vec3 origin(rng.uniform() * 100, rng.uniform() * 100, -10);
        const Vec3 target(rng.uniform() * 100, rng.uniform() * 100, 110);
        rays.push_back({origin, glm::normalize(target - origin)});
    }

    TestType single;
    single.build(boxes, 1);
    const auto expected = visits(single, rays);
    size_t visited = 0;
    for (const auto& seen : expected) visited += seen.size();
    REQUIRE(visited > rays.size()); // the rays meet boxes: the comparison below means something

    for (unsigned threads : {2u, 3u, 8u}) {
        INFO("threads: " << threads);
        TestType parallel;
        parallel.build(boxes, threads);
        CHECK(parallel.nodeCount() == single.nodeCount());
        CHECK(parallel.depth() == single.depth());
        CHECK(visits(parallel, rays) == expected);
    }
}
