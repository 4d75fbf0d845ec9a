// An AreaLight's `circular` (the ellipse inscribed in its parallelogram) and `orient` (turned
// to face each lit point): where its samples fall, what rays meet, and its density.
#include "tracer/lights.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;

namespace {

/// A light 2 wide along x and 1 deep along z, centred on (0, 4, 0), facing down.
scene::LightDesc lamp(bool circular, bool orient) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Area;
    l.origin = {-1, 4, -0.5};
    l.edgeA = {2, 0, 0};
    l.edgeB = {0, 0, 1};
    l.color = {1, 1, 1, 1};
    l.circular = circular;
    l.orient = orient;
    return l;
}

const glm::dvec3 kCenter{0, 4, 0};

/// (2a − 1)² + (2b − 1)² for the point's coordinates (a, b) along the unturned edges.
double ellipseRadius2(const glm::dvec3& target) {
    const double a = (target.x + 1) / 2, b = target.z + 0.5;
    return (2 * a - 1) * (2 * a - 1) + (2 * b - 1) * (2 * b - 1);
}

} // namespace

TEST_CASE("a circular area light's samples fill the ellipse inscribed in its parallelogram", "[lights]") {
    const Light light(lamp(true, false), 64);
    const glm::dvec3 below{0.3, 0, 0.2};
    double widest = 0;
    for (int i = 0; i < light.sampleCount(); ++i)
        for (glm::dvec2 jitter : {glm::dvec2(0.5), glm::dvec2(0.01, 0.99), glm::dvec2(0.99, 0.01)}) {
            const LightSample s = light.sample(below, i, jitter);
            CHECK(s.target.y == 4);
            CHECK(ellipseRadius2(s.target) <= 1 + 1e-12);
            widest = std::max(widest, ellipseRadius2(s.target));
        }
    CHECK(widest > 0.8);
    for (glm::dvec2 u : {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1), glm::dvec2(0.3, 0.9)})
        CHECK(ellipseRadius2(light.sampleUniformly(below, u).target) <= 1 + 1e-12);
    // The square light reaches its corners.
    const Light square(lamp(false, false), 64);
    CHECK(ellipseRadius2(square.sampleUniformly(below, {0, 0}).target) == Approx(2));
}

TEST_CASE("rays meet a circular area light inside its ellipse only, and its density counts its area",
          "[lights]") {
    const Light light(lamp(true, false), 16), square(lamp(false, false), 16);
    const glm::dvec3 from{0, 0, 0};
    auto toward = [&](glm::dvec3 target) { return Ray{from, glm::normalize(target - from)}; };
    // Inside the ellipse, and inside the parallelogram but outside the ellipse.
    for (glm::dvec3 inside : {glm::dvec3(0, 4, 0), glm::dvec3(0.9, 4, 0), glm::dvec3(0, 4, 0.45)}) {
        INFO(inside.x << " " << inside.z);
        CHECK(light.crossing(toward(inside), 100) == Approx(glm::length(inside)));
    }
    for (glm::dvec3 corner : {glm::dvec3(0.95, 4, 0.45), glm::dvec3(-0.9, 4, -0.4)}) {
        CHECK(light.crossing(toward(corner), 100) == kInfinity);
        CHECK(square.crossing(toward(corner), 100) == Approx(glm::length(corner)));
    }
    // Straight up to the centre at distance 4: d² / (area · cos θ), area π/4 · 2.
    const glm::dvec3 up{0, 1, 0};
    CHECK(light.areaPdf(from, up, 4) == Approx(16 / (kPi / 4 * 2)));
    CHECK(square.areaPdf(from, up, 4) == Approx(16 / 2.0));
}

TEST_CASE("an oriented area light faces every point it lights, its edges keeping their lengths", "[lights]") {
    const Light light(lamp(true, true), 64);
    for (glm::dvec3 point : {glm::dvec3(0, 0, 0), glm::dvec3(5, 4, 0), glm::dvec3(-3, 6, 2), glm::dvec3(0, 4, -7)}) {
        INFO(point.x << " " << point.y << " " << point.z);
        const glm::dvec3 facing = glm::normalize(point - kCenter);
        double widest = 0;
        for (int i = 0; i < light.sampleCount(); ++i) {
            const glm::dvec3 offset = light.sample(point, i, {0.5, 0.5}).target - kCenter;
            CHECK(std::abs(glm::dot(offset, facing)) < 1e-12);
            // Within the ellipse of half-axes 1 and 0.5: at most 1 from the centre.
            CHECK(glm::length(offset) <= 1 + 1e-12);
            widest = std::max(widest, glm::length(offset));
        }
        CHECK(widest > 0.85);
        // Seen from the point, it is as large as the unturned light is from straight below.
        const Ray atCenter{point, -facing};
        const double distance = glm::length(point - kCenter);
        CHECK(light.crossing(atCenter, 100) == Approx(distance));
        CHECK(light.areaPdf(point, -facing, distance) == Approx(distance * distance / (kPi / 4 * 2)));
    }
}

TEST_CASE("a sphere light samples the disc facing each point, and is seen as its sphere", "[lights]") {
    scene::LightDesc desc;
    desc.kind = scene::LightKind::Sphere;
    desc.origin = kCenter;
    desc.radius = 0.5;
    desc.color = {1, 1, 1, 1};
    const Light light(desc, 16);
    REQUIRE(light.hasArea());
    for (glm::dvec3 point : {glm::dvec3(0, 0, 0), glm::dvec3(3, 4, 1)}) {
        const glm::dvec3 facing = glm::normalize(point - kCenter);
        for (int i = 0; i < light.sampleCount(); ++i) {
            const glm::dvec3 offset = light.sample(point, i, {0.3, 0.7}).target - kCenter;
            CHECK(std::abs(glm::dot(offset, facing)) < 1e-12);
            CHECK(glm::length(offset) <= 0.5 + 1e-12);
        }
    }
    // Seen: the sphere's near side, along any ray toward it, and nothing past tMax.
    const Ray down{{0, 10, 0}, {0, -1, 0}};
    CHECK(light.seenAt(down, 100) == Approx(5.5));
    CHECK(light.seenAt(down, 5) == kInfinity);
    const Ray beside{{0.49, 10, 0}, {0, -1, 0}}, past{{0.51, 10, 0}, {0, -1, 0}};
    CHECK(light.seenAt(beside, 100) < kInfinity);
    CHECK(light.seenAt(past, 100) == kInfinity);
    // From inside it, the far wall.
    CHECK(light.seenAt(Ray{kCenter, {1, 0, 0}}, 100) == Approx(0.5));
}

TEST_CASE("a cylinder light is seen as the open tube of its radius around its segment", "[lights]") {
    scene::LightDesc desc;
    desc.kind = scene::LightKind::Cylinder;
    desc.from = {-1, 4, 0};
    desc.to = {1, 4, 0};
    desc.radius = 0.1;
    desc.color = {1, 1, 1, 1};
    const Light light(desc, 8);
    CHECK(light.seenAt(Ray{{0.5, 0, 0}, {0, 1, 0}}, 100) == Approx(3.9));
    CHECK(light.seenAt(Ray{{0.5, 0, 0.11}, {0, 1, 0}}, 100) == kInfinity);
    CHECK(light.seenAt(Ray{{1.05, 0, 0}, {0, 1, 0}}, 100) == kInfinity); // past its end
    // Along its axis from beyond an end: the tube is open, so it is not met.
    CHECK(light.seenAt(Ray{{-3, 4, 0}, {1, 0, 0}}, 100) == kInfinity);
    // A ray that enters past an end meets the inside of the far wall within the segment.
    const glm::dvec3 from{-1.2, 4.05, -1};
    const Ray slanted{from, glm::normalize(glm::dvec3(-0.8, 4, 0.1) - from)};
    const double t = light.seenAt(slanted, 100);
    REQUIRE(t < kInfinity);
    const glm::dvec3 at = slanted.origin + t * slanted.dir;
    CHECK(at.x >= -1);
    CHECK(std::hypot(at.y - 4, at.z) == Approx(0.1));
}
