// Blob crossings and surface points against the field in long double: one sphere (an exact
// sphere), blended spheres and cylinders with a negative component, lines along and across a
// cylinder's axis, far lines.
#include "geometry_test_support.hpp"

#include "tracer/geometry/blob.hpp"

#include <memory>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

scene::BlobShape blobOf(double threshold, std::vector<scene::BlobComponent> components) {
    auto desc = std::make_shared<scene::BlobDesc>();
    desc->threshold = threshold;
    desc->components = std::move(components);
    return {desc};
}

scene::BlobComponent sphere(Vec3 c, double r, double s = 1) {
    return {false, c, c, r, s};
}
scene::BlobComponent cylinder(Vec3 a, Vec3 b, double r, double s = 1) {
    return {true, a, b, r, s};
}

/// The field in long double, from its definition: strength · (1 − (d / r)²)² within r of the
/// centre or the segment.
struct ExactBlob {
    scene::BlobDesc desc;

    LD field(const LVec& p) const {
        LD sum = 0;
        for (const scene::BlobComponent& c : desc.components) {
            const LVec a(c.a), axis = LVec(c.b) - LVec(c.a);
            LVec nearest = a;
            if (c.cylinder) {
                LD s = dot(p - a, axis) / dot(axis, axis);
                s = std::clamp(s, LD(0), LD(1));
                nearest = a + s * axis;
            }
            const LVec v = p - nearest;
            const LD d2 = dot(v, v), r2 = LD(c.radius) * c.radius;
            if (d2 < r2) sum += c.strength * (1 - d2 / r2) * (1 - d2 / r2);
        }
        return sum;
    }
    bool inside(const LVec& p) const { return field(p) > desc.threshold; }
    /// (threshold − field) over the gradient's length: a distance near the surface.
    LD distance(const LVec& p) const {
        const LD h = 1e-7L;
        const LVec dx(h, 0, 0), dy(0, h, 0), dz(0, 0, h);
        const LVec g((field(p + dx) - field(p - dx)) / (2 * h),
                     (field(p + dy) - field(p - dy)) / (2 * h),
                     (field(p + dz) - field(p - dz)) / (2 * h));
        const LD len = length(g);
        const LD gap = desc.threshold - field(p);
        return len > 0 ? gap / len : gap;
    }
};

const std::vector<scene::BlobComponent> kBlend = {sphere({-0.6, 0, 0}, 1), sphere({0.6, 0, 0}, 1),
                                                  cylinder({0, -1, 0}, {0, 1.2, 0.3}, 0.5, 1.2),
                                                  sphere({0.3, 0.3, -0.6}, 0.5, -1)};
const std::vector<scene::BlobComponent> kChain = {cylinder({-1, 0, 0}, {0, 0.8, 0}, 0.45),
                                                  cylinder({0, 0.8, 0}, {1, 0, 0.5}, 0.45),
                                                  cylinder({1, 0, 0.5}, {1.5, -0.8, 0}, 0.35, 2)};

} // namespace

TEST_CASE("blob: one sphere component is a sphere of the radius where the field is the "
          "threshold") {
    // strength · (1 − (d/r)²)² = threshold at d = r · √(1 − √(threshold / strength)).
    const BlobGeometry g(blobOf(0.25, {sphere({0, 0, 0}, 2)}));
    const double radius = 2 * std::sqrt(0.5);
    CrossingList list;
    const Ray across{{-5, 0.3, 0}, {1, 0, 0}};
    g.crossLine(across, list);
    REQUIRE(list.count == 2);
    const double half = std::sqrt(radius * radius - 0.09);
    CHECK(list[0].t == Approx(5 - half).epsilon(1e-12));
    CHECK(list[1].t == Approx(5 + half).epsilon(1e-12));
    const SurfacePoint sp = g.surfaceAt(across, list[0]);
    CHECK(glm::length(sp.point) == Approx(radius).epsilon(1e-12));
    CHECK(sp.normal.x == Approx(-half / radius));
    CHECK(g.bounds().hi.x >= 2);
    CHECK(g.bounds().lo.y <= -2);
}

TEST_CASE("blob: random lines against the exact field") {
    for (const auto& [name, threshold, components] :
         {std::tuple{"blend", 0.5, kBlend}, std::tuple{"chain", 0.3, kChain}}) {
        INFO(name);
        const BlobGeometry g(blobOf(threshold, components));
        const ExactBlob exact{{threshold, components}};
        const Bounds3 b = g.bounds();
        Random rng(101);
        int most = 0;
        for (int i = 0; i < 400; ++i) {
            const Ray ray = rng.lineThrough(rng.pointIn(b), 5);
            CrossingList list;
            g.crossLine(ray, list);
            checkAlternates(
                list, ray, [&](const LVec& q) { return exact.inside(q); }, true);
            most = std::max(most, list.count);
        }
        CHECK(most >= 4);
    }
}

TEST_CASE("blob: lines along and across a cylinder's axis") {
    const std::vector<scene::BlobComponent> rod = {cylinder({0, -1, 0}, {0, 1, 0}, 0.5)};
    const BlobGeometry g(blobOf(0.25, rod));
    const ExactBlob exact{{0.25, rod}};
    const double reach = 0.5 * std::sqrt(0.5);
    CrossingList list;
    // Along the axis, off it: through the body only... and the round ends.
    const Ray along{{0.1, -5, 0}, {0, 1, 0}};
    g.crossLine(along, list);
    REQUIRE(list.count == 2);
    const double cap = std::sqrt(reach * reach - 0.01);
    CHECK(list[0].t == Approx(4 - cap).epsilon(1e-12));
    CHECK(list[1].t == Approx(6 + cap).epsilon(1e-12));
    // Across it, level with the body, and beyond an end through a round end.
    for (double y : {0.3, 1.1, -1.2}) {
        INFO("y " << y);
        const Ray across{{-3, y, 0.05}, {1, 0, 0}};
        g.crossLine(across, list);
        checkAlternates(
            list, across, [&](const LVec& q) { return exact.inside(q); }, true);
    }
    g.crossLine({{-3, 0.3, 0.05}, {1, 0, 0}}, list);
    CHECK(list.count == 2);
}

TEST_CASE("blob: surface points, outward normals and error bounds") {
    const BlobGeometry g(blobOf(0.5, kBlend));
    const ExactBlob exact{{0.5, kBlend}};
    Random rng(102);
    int checked = 0;
    for (double far : {5.0, 1e5}) {
        for (int i = 0; i < 300; ++i) {
            const Ray ray = rng.lineThrough(rng.inBox(0.8), far);
            CrossingList list;
            g.crossLine(ray, list);
            for (int k = 0; k < list.count; ++k) {
                const SurfacePoint sp = g.surfaceAt(ray, list[k]);
                checkUnit(sp.normal);
                const LVec q(sp.point);
                const LD step = 1e-6L;
                CHECK(exact.inside(q - step * LVec(sp.normal)));
                CHECK_FALSE(exact.inside(q + step * LVec(sp.normal)));
                checkBoundContainsExact(
                    sp, ray, [&](const LVec& p) { return exact.distance(p); }, list[k].t);
                ++checked;
            }
        }
    }
    CHECK(checked > 500);
}

TEST_CASE("blob: components that take away only leave nothing") {
    const BlobGeometry g(blobOf(0.5, {sphere({0, 0, 0}, 1, -1)}));
    CHECK(g.bounds().empty());
    CrossingList list;
    g.crossLine({{-3, 0, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
}
