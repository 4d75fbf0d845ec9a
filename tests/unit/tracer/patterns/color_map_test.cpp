// Colour maps: POV-Ray's blend-map lookup (clamped ends, linear between stops, sharp edges).
#include <catch2/catch.hpp>

#include "tracer/patterns/color_map.hpp"

#include <cmath>
#include <limits>

using namespace crt;
using tracer::ColorMap;
using tracer::Vec3;
using tracer::Vec4;

namespace {

scene::Color grey(double v) {
    return {v, v, v, 1};
}

} // namespace

TEST_CASE("a colour map is linear between stops and clamped outside them", "[patterns]") {
    ColorMap map({{0.2, grey(0.1)}, {0.6, grey(0.5)}, {1.0, grey(0.9)}});
    CHECK(map.at(-3).x == 0.1);
    CHECK(map.at(0.2).x == 0.1);
    CHECK(map.at(0.4).x == Approx(0.3));
    CHECK(map.at(0.6).x == 0.5);
    CHECK(map.at(0.8).x == Approx(0.7));
    CHECK(map.at(1.0).x == 0.9);
    CHECK(map.at(7).x == 0.9);
    CHECK(map.at(std::numeric_limits<double>::quiet_NaN()).x == 0.9);
}

TEST_CASE("two stops at one value make a sharp edge", "[patterns]") {
    ColorMap map({{0, grey(0)}, {0.5, grey(0.2)}, {0.5, grey(0.8)}, {1, grey(1)}});
    CHECK(map.at(0.25).x == Approx(0.1));
    CHECK(map.at(0.5).x == 0.2); // the first of the two, as POV-Ray
    CHECK(map.at(std::nextafter(0.5, 1.0)).x == Approx(0.8));
    CHECK(map.at(0.75).x == Approx(0.9));
}

TEST_CASE("a two-stop map at 0 and 1 is the 2015 mix of a and b, bit for bit", "[patterns]") {
    scene::Color a{0.9, 0.3, 0.05, 1}, b{0.1, 0.7, 0.95, 1};
    ColorMap map({{0, a}, {1, b}});
    CHECK(map.at(1.0) == Vec4(b.r, b.g, b.b, 1)); // the top stop itself (2015: a + (b - a) · 1)
    for (double t : {0.0, 0.1, 0.3333333333, 0.5, 0.77, 0.999}) {
        Vec3 old = Vec3(a.r, a.g, a.b) + (Vec3(b.r, b.g, b.b) - Vec3(a.r, a.g, a.b)) * t;
        CHECK(Vec3(map.at(t)) == old);
    }
}

TEST_CASE("discrete patterns read stops by position", "[patterns]") {
    ColorMap map({{0, grey(0.1)}, {0.5, grey(0.5)}, {1, grey(0.9)}});
    CHECK(map.entry(0).x == 0.1);
    CHECK(map.entry(1).x == 0.5);
    CHECK(map.entry(2).x == 0.9);
    CHECK(map.entry(5).x == 0.9);
}

TEST_CASE("a colour map carries its stops' alpha", "[patterns]") {
    ColorMap opaque({{0, grey(0)}, {1, grey(1)}});
    CHECK_FALSE(opaque.translucent());
    ColorMap lace({{0, {1, 1, 1, 1}}, {1, {1, 1, 1, 0}}});
    CHECK(lace.translucent());
    CHECK(lace.at(0.25).a == Approx(0.75));
    CHECK(lace.entry(1).a == 0);
}
