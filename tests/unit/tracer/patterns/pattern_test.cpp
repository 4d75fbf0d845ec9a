// Patterns as fields: defaults, turbulence that moves points and nothing else, determinism.
#include <catch2/catch.hpp>

#include "tracer/patterns/pattern.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

using namespace crt;
using tracer::patternValue;
using tracer::Vec3;

TEST_CASE("turbulence 0 reads the pattern at the point itself", "[patterns]") {
    auto gradient = scene::defaultTexture(scene::TextureKind::Gradient);
    for (double x : {0.1, 0.35, 0.8}) CHECK(patternValue(gradient, Vec3(x, 5, -2)) == Approx(x));
}

TEST_CASE("turbulence moves the point, by about its amount, the same way every time",
          "[patterns]") {
    auto calm = scene::defaultTexture(scene::TextureKind::Gradient);
    auto stirred = calm;
    stirred.displacement = Vec3(0.05, 0, 0);
    int moved = 0;
    for (int i = 0; i < 200; ++i) {
        Vec3 p(0.3 + 0.001 * i, 0.37 * i, -0.11 * i);
        double shift = patternValue(stirred, p) - patternValue(calm, p);
        CHECK(std::abs(shift) < 0.05 * 2.5); // |noise| < ~1, octaves summing to < 2
        moved += std::abs(shift) > 1e-4;
        CHECK(patternValue(stirred, p) == patternValue(stirred, p));
    }
    CHECK(moved > 150);
    auto sideways = calm;
    sideways.displacement = Vec3(0, 0.5, 0.5); // moving along y and z leaves a gradient in x alone
    CHECK(patternValue(sideways, Vec3(0.4, 1.3, 2.1)) == Approx(0.4));
}

TEST_CASE("discrete patterns give the position of their colour", "[patterns]") {
    auto hexagon = scene::defaultTexture(scene::TextureKind::Hexagon);
    bool seen[3] = {false, false, false};
    for (int i = 0; i < 400; ++i) {
        double v = patternValue(hexagon, Vec3(0.173 * i, 0, 0.311 * i));
        REQUIRE((v == 0 || v == 1 || v == 2));
        seen[static_cast<int>(v)] = true;
    }
    CHECK((seen[0] && seen[1] && seen[2]));
    auto brick = scene::defaultTexture(scene::TextureKind::Brick);
    CHECK(patternValue(brick, Vec3(4, 1.5, 1)) == 1);  // inside a brick
    CHECK(patternValue(brick, Vec3(4, -0.2, 1)) == 0); // in the joint under a course
    CHECK(patternValue(brick, Vec3(4, 1.5, 2)) == 0);  // in a joint between two bricks' ends
}

TEST_CASE("Mandel is 1 inside the set and the share of iterations outside", "[patterns]") {
    auto mandel = scene::defaultTexture(scene::TextureKind::Mandel);
    mandel.iterations = 50;
    CHECK(patternValue(mandel, Vec3(0, 0, 0)) == 1);
    CHECK(patternValue(mandel, Vec3(-1, 0, 0)) == 1);
    CHECK(patternValue(mandel, Vec3(3, 0, 0)) == 0); // escapes at the first iteration
    CHECK(patternValue(mandel, Vec3(0.5, 0, 0)) ==
          Approx(3.0 / 50)); // |z| passes 2 at the fourth step
}

TEST_CASE("Crackle is 0 on the walls between its cells and grows inside them", "[patterns]") {
    auto crackle = scene::defaultTexture(scene::TextureKind::Crackle);
    double lowest = 1, highest = 0;
    for (int i = 0; i < 2000; ++i) {
        double v = patternValue(crackle, Vec3(0.0137 * i, 0.021 * i, -0.0071 * i));
        REQUIRE(v >= 0); // the second-nearest point is never nearer than the nearest
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    CHECK(lowest < 0.02);
    CHECK(highest > 0.4);
    auto nearest = crackle;
    nearest.form = Vec3(1, 0, 0);
    auto manhattan = nearest;
    manhattan.metric = 1;
    Vec3 p(0.3, 1.7, -2.2);
    CHECK(patternValue(manhattan, p) >= patternValue(nearest, p) - 1e-12);
}

TEST_CASE("Cells is one value in each unit cube", "[patterns]") {
    auto cells = scene::defaultTexture(scene::TextureKind::Cells);
    CHECK(patternValue(cells, Vec3(2.1, -0.5, 7.2)) == patternValue(cells, Vec3(2.9, -0.1, 7.8)));
    CHECK(patternValue(cells, Vec3(2.1, -0.5, 7.2)) != patternValue(cells, Vec3(3.1, -0.5, 7.2)));
}

TEST_CASE("Slope reads the normal against its direction", "[patterns]") {
    auto slope = scene::defaultTexture(scene::TextureKind::Slope);
    CHECK(patternValue(slope, Vec3(5, 5, 5), Vec3(0, 1, 0)) == Approx(1));
    CHECK(patternValue(slope, Vec3(5, 5, 5), Vec3(1, 0, 0)) == Approx(0.5));
    CHECK(patternValue(slope, Vec3(5, 5, 5), Vec3(0, -1, 0)) == Approx(0).margin(1e-12));
    CHECK(patternValue(slope, Vec3(0, 0, 0), glm::normalize(Vec3(1, 1, 0))) == Approx(0.75));
}
