// A BVH whose leaves are groups of up to four items (a mesh's triangle quads): every item is
// in one group, and a ray visits the group of every item whose box it meets.
#include "tracer/bvh.hpp"
#include "tracer/sampling.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace crt::tracer;

namespace {

/// A grouped BVH over `boxes` and its groups' items, numbered in the order they were made.
template <typename Tree>
struct GroupedBvh {
    Tree bvh;
    std::vector<std::vector<int32_t>> groups;

    GroupedBvh(const std::vector<Bounds3>& boxes, unsigned threads) {
        const size_t expected = bvh.buildGrouped(boxes.size(), [&](size_t i) { return boxes[i]; }, threads);
        auto makeGroup = [&](std::span<const int32_t> items) {
            groups.emplace_back(items.begin(), items.end());
            return static_cast<int32_t>(groups.size() - 1);
        };
        bvh.groupLeaves(makeGroup);
        CHECK(groups.size() == expected);
    }

    /// The items of the groups the ray's traversal visits.
    std::set<int32_t> visited(const Ray& ray) const {
        std::set<int32_t> items;
        RayStats stats;
        const double tMax = kInfinity;
        bvh.traverse(LazyBoxRay(ray), tMax, stats, [&](int32_t group) {
            for (int32_t item : groups.at(static_cast<size_t>(group))) items.insert(item);
            return true;
        });
        return items;
    }
};

/// Each item in exactly one group, of one to four items.
template <typename Grouped>
void checkPartition(const Grouped& grouped, size_t itemCount) {
    std::map<int32_t, int> seen;
    for (const std::vector<int32_t>& group : grouped.groups) {
        CHECK(!group.empty());
        CHECK(group.size() <= 4);
        for (int32_t item : group) ++seen[item];
    }
    REQUIRE(seen.size() == itemCount);
    for (const auto& [item, times] : seen) CHECK(times == 1);
}

/// Every item whose box the ray meets (tested in double) is among the visited groups' items.
template <typename Grouped>
void checkRaysFindBoxes(const Grouped& grouped, const std::vector<Bounds3>& boxes, SampleRng& rng, int rays) {
    int met = 0;
    for (int r = 0; r < rays; ++r) {
        const Vec3 from(rng.uniform() * 120 - 10, rng.uniform() * 120 - 10, -20);
        const Ray ray{from, glm::normalize(Vec3(rng.uniform() * 100, rng.uniform() * 100, 100) - from)};
        const std::set<int32_t> visited = grouped.visited(ray);
        const BoxRay boxRay(ray);
        for (size_t i = 0; i < boxes.size(); ++i) {
            if (!boxRay.hits(boxes[i], 0, kInfinity)) continue;
            ++met;
            REQUIRE(visited.count(static_cast<int32_t>(i)) == 1);
        }
    }
    CHECK(met > rays);
}

} // namespace

TEMPLATE_TEST_CASE("a grouped BVH puts every item in one group of up to four, and rays find them", "[bvh]",
                   WideBvh<4>, WideBvh<8>) {
    SampleRng rng(3, 0, 0);
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 c(rng.uniform() * 100, rng.uniform() * 100, rng.uniform() * 100);
        const Vec3 half(0.2 + rng.uniform());
        boxes.push_back({c - half, c + half});
    }
    // Twelve boxes whose centroids coincide: no split divides them, so one leaf holds all
    // twelve, as three groups.
    for (int i = 0; i < 12; ++i) boxes.push_back({Vec3(50 - 0.1 * i), Vec3(50 + 0.1 * i)});
    for (unsigned threads : {1u, 3u}) {
        const GroupedBvh<TestType> grouped(boxes, threads);
        checkPartition(grouped, boxes.size());
        // A range of up to four is always one leaf: groups hold more than 2.5 items on average.
        CHECK(grouped.groups.size() * 5 < boxes.size() * 2);
        checkRaysFindBoxes(grouped, boxes, rng, 300);
        const std::set<int32_t> atCentre = grouped.visited(Ray{{50, 50, -20}, {0, 0, 1}});
        for (int i = 0; i < 12; ++i) CHECK(atCentre.count(static_cast<int32_t>(20000 + i)) == 1);
    }
}

TEMPLATE_TEST_CASE("a grouped BVH of a few items is one group under their joint box", "[bvh]", WideBvh<4>,
                   WideBvh<8>) {
    const std::vector<Bounds3> boxes = {{{0, 0, 0}, {1, 1, 1}}, {{5, 0, 0}, {6, 1, 1}}, {{0, 5, 0}, {1, 6, 1}}};
    const GroupedBvh<TestType> grouped(boxes, 1);
    REQUIRE(grouped.groups.size() == 1);
    checkPartition(grouped, boxes.size());
    CHECK(grouped.visited(Ray{{5.5, 0.5, -1}, {0, 0, 1}}).size() == 3);
    CHECK(grouped.visited(Ray{{0.5, 3, -1}, {0, 0, 1}}).size() == 3); // between them, in the joint box
    CHECK(grouped.visited(Ray{{9, 9, -1}, {0, 0, 1}}).empty());
}
