// The four-triangle float test rules out no triangle the exact test crosses, at any scale
// and offset, and does rule out those a line clearly misses.
#include "tracer/geometry/triangle.hpp"
#include "tracer/geometry/triangle_quad.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>

using namespace crt::tracer;

namespace {

using Triangle = std::array<Vec3, 3>;

/// Four triangles of about `size` around `at` (one a sliver), in the frame of a mesh that
/// reaches `meshReach` times their size beyond them.
struct Quad {
    std::array<Triangle, 4> triangles;
    QuadFrame frame;
    TriangleQuad quad;

    Quad(std::mt19937_64& rng, Vec3 at, double size, double meshReach = 0) {
        std::uniform_real_distribution<double> unit(-1, 1);
        auto near = [&] { return at + size * Vec3(unit(rng), unit(rng), unit(rng)); };
        Bounds3 bounds;
        for (Triangle& t : triangles) {
            t = {near(), near(), near()};
            for (const Vec3& p : t) bounds.include(p);
        }
        // A sliver: its third corner almost on its first edge.
        triangles[3][2] = 0.5 * (triangles[3][0] + triangles[3][1]) + 1e-4 * size * Vec3(unit(rng), unit(rng), unit(rng));
        bounds.include(triangles[3][2]);
        bounds.include(at + meshReach * size * Vec3(1, -0.5, 0.7));
        frame.centre = bounds.centroid();
        const Vec3 reach = glm::max(bounds.hi - frame.centre, frame.centre - bounds.lo);
        frame.radius = (1 + 0x1p-40) * std::max({reach.x, reach.y, reach.z});
        const int32_t ids[] = {0, 1, 2, 3};
        quad = makeTriangleQuad(frame, ids, [&](int32_t i, int k) { return triangles[static_cast<size_t>(i)][static_cast<size_t>(k)]; });
    }

    /// The point of triangle i at barycentric weights (1 − b − c, b, c).
    Vec3 point(size_t i, double b, double c) const {
        const Triangle& t = triangles[i];
        return (1 - b - c) * t[0] + b * t[1] + c * t[2];
    }
};

bool crosses(const Triangle& t, const Ray& ray) {
    const Vec3 p[3] = {t[0], t[1], t[2]};
    double at;
    Vec3 weights;
    return crossTriangle(p, ray, at, weights);
}

} // namespace

TEST_CASE("a triangle quad rules out no triangle that the exact test finds crossed", "[mesh]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    int crossings = 0;
    for (double size : {1e-6, 1e-3, 1.0, 1e3, 1e9}) {
        for (double offset : {0.0, 1e6, -3.3e4}) {
            for (int round = 0; round < 40; ++round) {
                // Where the rest of the mesh is far, its frame's rounding outweighs the rest.
                const double meshReach = round % 2 == 0 ? 0 : 1e4;
                const Quad q(rng, Vec3(offset, -0.5 * offset, 0.25 * offset) + size * Vec3(0.1, 0.2, 0.3), size, meshReach);
                for (double distance : {1e-2, 1.0, 1e3}) {
                    // Aimed at each triangle's edges, corners and inside, from all around.
                    for (size_t i = 0; i < 4; ++i) {
                        for (int aim = 0; aim < 8; ++aim) {
                            const double b = aim < 3 ? 0.5 * aim : unit(rng), c = aim == 1 ? 0 : aim < 3 ? 1 - b : unit(rng) * (1 - b);
                            const Vec3 target = q.point(i, b, c);
                            const Vec3 from = target + distance * size * glm::normalize(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
                            const Ray ray{from, (target - from) * (0.5 + unit(rng))};
                            const int lanes = q.quad.mayCross(QuadRay(ray, q.frame));
                            for (size_t lane = 0; lane < 4; ++lane) {
                                if (!crosses(q.triangles[lane], ray)) continue;
                                ++crossings;
                                INFO("size " << size << ", offset " << offset << ", mesh " << meshReach << ", distance " << distance
                                                << ", lane " << lane);
                                REQUIRE((lanes & (1 << lane)) != 0);
                            }
                        }
                    }
                }
            }
        }
    }
    CHECK(crossings > 10000);
}

TEST_CASE("a triangle quad rules out the triangles a line misses by a twentieth of their size", "[mesh]") {
    // A mesh's triangles of 0.01 in a mesh of 8 units, seen from 10 units (a terrain's case)
    // and from 10,000.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    int misses = 0, kept = 0;
    for (int round = 0; round < 200; ++round) {
        const double distance = round % 2 == 0 ? 10 : 1e4;
        Quad q(rng, Vec3(4 * unit(rng), 0, 4 * unit(rng)), 0.01);
        q.frame.radius = 4; // the whole mesh's
        q.frame.centre = Vec3(2, 0, 2);
        for (size_t i = 0; i < 4; ++i) {
            // Beyond an edge: a weight of -0.05 to -0.5.
            const double b = -0.05 - 0.45 * unit(rng), c = unit(rng);
            const Vec3 target = q.point(i, b, c);
            const Vec3 from = target + distance * glm::normalize(Vec3(unit(rng) - 0.5, 1, unit(rng) - 0.5));
            const Ray ray{from, target - from};
            if (crosses(q.triangles[i], ray)) continue;
            ++misses;
            kept += (q.quad.mayCross(QuadRay(ray, q.frame)) >> i) & 1;
        }
    }
    CHECK(misses > 700);
    CHECK(kept == 0);
}

TEST_CASE("a quad of fewer than four triangles leaves its other lanes out", "[mesh]") {
    const Vec3 corners[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const int32_t ids[] = {5, 9};
    const QuadFrame frame{{0, 0, 0}, 1};
    const TriangleQuad quad = makeTriangleQuad(frame, ids, [&](int32_t, int k) { return corners[k]; });
    CHECK(quad.triangle[0] == 5);
    CHECK(quad.triangle[1] == 9);
    CHECK(quad.triangle[2] == -1);
    CHECK(quad.triangle[3] == -1);
    // Through both triangles (they are one), and past them.
    CHECK(quad.mayCross(QuadRay(Ray{{0, 0, -1}, {0, 0, 1}}, frame)) == 0b11);
    CHECK(quad.mayCross(QuadRay(Ray{{3, 0, -1}, {0, 0, 1}}, frame)) == 0);
}
