// The preview's camera math: orbit, pan, dolly and zoom.
#include "preview/camera_controls.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

using namespace crt;
using namespace crt::crtc::preview;

namespace {

scene::CameraDesc sample() {
    scene::CameraDesc c;
    c.position = {1.0, 2.0, -5.0};
    c.pointing = {0.5, 0.8, 0.3};
    c.fov = 45;
    return c;
}

double distance(const scene::CameraDesc& c) { return glm::length(c.position - c.pointing); }

} // namespace

TEST_CASE("orbit keeps the point looked at and its distance", "[preview]") {
    const scene::CameraDesc start = sample();
    for (auto [yaw, pitch] : {std::pair{30.0, 0.0}, {0.0, 20.0}, {-75.0, -40.0}, {400.0, 10.0}}) {
        const scene::CameraDesc moved = orbit(start, yaw, pitch);
        CHECK(moved.pointing == start.pointing);
        CHECK(distance(moved) == Approx(distance(start)));
        CHECK(moved.position != start.position);
    }
}

TEST_CASE("orbit turns about the up vector and rises with a positive pitch", "[preview]") {
    scene::CameraDesc c;
    c.position = {0, 0, -4};
    c.pointing = {0, 0, 0};
    // A quarter turn to the camera's right (+x, the renderer's left-handed right).
    const scene::CameraDesc turned = orbit(c, 90, 0);
    CHECK(turned.position.x == Approx(4));
    CHECK(turned.position.z == Approx(0).margin(1e-12));
    const scene::CameraDesc risen = orbit(c, 0, 30);
    CHECK(risen.position.y > 0);
    CHECK(risen.position.y == Approx(4 * std::sin(glm::radians(30.0))));
}

TEST_CASE("orbit stops short of the up vector instead of flipping over", "[preview]") {
    scene::CameraDesc c;
    c.position = {0, 0, -4};
    c.pointing = {0, 0, 0};
    const scene::CameraDesc top = orbit(c, 0, 120);
    const double angle = glm::degrees(std::acos(glm::dot(glm::normalize(top.position), glm::dvec3(0, 1, 0))));
    CHECK(angle == Approx(1.0));
    CHECK(top.position.z < 0); // still on the camera's side
}

TEST_CASE("pan keeps the distance and the direction of view", "[preview]") {
    const scene::CameraDesc start = sample();
    const scene::CameraDesc moved = pan(start, 0.25, -0.1);
    CHECK(distance(moved) == Approx(distance(start)));
    const glm::dvec3 before = start.position - start.pointing, after = moved.position - moved.pointing;
    CHECK(after.x == Approx(before.x));
    CHECK(after.y == Approx(before.y));
    CHECK(after.z == Approx(before.z));
    CHECK(moved.pointing != start.pointing);
}

TEST_CASE("pan follows the mouse: the scene moves right, so the camera moves left", "[preview]") {
    scene::CameraDesc c;
    c.position = {0, 0, -4};
    c.pointing = {0, 0, 0};
    c.fov = 90; // the view is 2 × 4 × tan 45° = 8 units high at the pointing point
    const scene::CameraDesc moved = pan(c, 0.5, 0.25);
    CHECK(moved.position.x == Approx(-4));
    CHECK(moved.position.y == Approx(-2));
    CHECK(moved.position.z == Approx(-4));
}

TEST_CASE("dolly moves along the line of view and never reaches the point looked at", "[preview]") {
    const scene::CameraDesc start = sample();
    CHECK(distance(dolly(start, 0.5)) == Approx(distance(start) / 2));
    CHECK(dolly(start, 0.5).pointing == start.pointing);
    CHECK(distance(dolly(start, 0)) == Approx(distance(start))); // refused
    CHECK(distance(dolly(start, 1e-12)) > 0);
}

TEST_CASE("the field of view stays within [1, 170] degrees", "[preview]") {
    CHECK(withFov(sample(), 500).fov == 170);
    CHECK(withFov(sample(), -3).fov == 1);
    CHECK(withFov(sample(), 30).fov == 30);
    CHECK(withFov(sample(), std::nan("")).fov == 45);
}
