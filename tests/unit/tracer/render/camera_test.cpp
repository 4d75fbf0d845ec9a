// The cameras' pixel-to-ray mappings (docs/rendering.md, "Camera"): orthographic, fisheye
// and cylindrical against their formulas.
#include "tracer/camera.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;

namespace {

scene::CameraDesc lookingAlongZ(scene::Projection projection, double fov = 60) {
    scene::CameraDesc c;
    c.position = {0, 0, -5};
    c.pointing = {0, 0, 0};
    c.fov = fov;
    c.projection = projection;
    return c;
}

double degreesBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180 / kPi;
}

void checkNear(const Vec3& a, const Vec3& b) {
    INFO("(" << a.x << ", " << a.y << ", " << a.z << ") against (" << b.x << ", " << b.y << ", " << b.z << ")");
    CHECK(glm::distance(a, b) < 1e-12);
}

} // namespace

TEST_CASE("camera: an orthographic camera's pixels are parallel rays over a view `width` wide",
          "[camera]") {
    scene::CameraDesc desc = lookingAlongZ(scene::Projection::Orthographic);
    desc.width = 4;
    const Camera camera(desc, 200, 100, 1);
    // The image's corners and middle: x from -2 to 2, y from 1 to -1 (half as high).
    checkNear(camera.ray(0, 0).origin, {-2, 1, -5});
    checkNear(camera.ray(200, 100).origin, {2, -1, -5});
    checkNear(camera.ray(100, 50).origin, {0, 0, -5});
    checkNear(camera.ray(150, 25).origin, {1, 0.5, -5});
    for (double u : {0.0, 37.5, 200.0}) checkNear(camera.ray(u, 10).dir, {0, 0, 1});
    // Without a width, the view is as high as the pinhole camera's at the point looked at.
    desc.width = 0;
    const Camera fromFov(desc, 200, 100, 1);
    checkNear(fromFov.ray(100, 0).origin, {0, 5 * std::tan(30 * kPi / 180), -5});
}

TEST_CASE("camera: an orthographic camera's lens rays meet on the focal plane", "[camera]") {
    scene::CameraDesc desc = lookingAlongZ(scene::Projection::Orthographic);
    desc.width = 4;
    desc.aperture = 300;
    desc.focalDistance = 3;
    const Camera camera(desc, 200, 100, 8);
    REQUIRE(camera.usesLens());
    const Vec3 focus = camera.ray(150, 25).origin + Vec3(0, 0, 3);
    for (Vec2 lens : {Vec2(0.1, 0.2), Vec2(0.9, 0.5), Vec2(0.4, 0.95)}) {
        const Ray r = camera.lensRay(150, 25, lens);
        CHECK(r.origin.z == Approx(-5));
        CHECK(glm::distance(r.origin, camera.ray(150, 25).origin) > 1e-3);
        checkNear(r.origin + r.dir * (3 / r.dir.z), focus);
    }
}

TEST_CASE("camera: a fisheye's angle from the view grows with the distance from the middle", "[camera]") {
    const Camera camera(lookingAlongZ(scene::Projection::Fisheye, 180), 300, 200, 1);
    checkNear(camera.ray(150, 100).dir, {0, 0, 1});
    // The circle's radius is half the image's height: fov/2 there, fov/4 halfway.
    CHECK(degreesBetween(camera.ray(250, 100).dir, {0, 0, 1}) == Approx(90));
    CHECK(degreesBetween(camera.ray(150, 50).dir, {0, 0, 1}) == Approx(45));
    CHECK(camera.ray(150, 50).dir.y > 0); // up in the image is up in the scene
    CHECK(camera.ray(200, 100).dir.x > 0);
    CHECK(camera.sees(150 + 70, 100 + 70));
    CHECK(!camera.sees(150 + 72, 100 + 72));
    CHECK(!camera.sees(0, 0));
    CHECK(Camera(lookingAlongZ(scene::Projection::Pinhole), 300, 200, 1).sees(0, 0));
}

TEST_CASE("camera: a cylindrical camera turns by fov across and rises straight", "[camera]") {
    const Camera camera(lookingAlongZ(scene::Projection::Cylindrical, 240), 400, 100, 1);
    checkNear(camera.ray(200, 50).dir, {0, 0, 1});
    // Across: the angle around up is (u/W - 1/2)·fov.
    const Ray left = camera.ray(0, 50), quarter = camera.ray(300, 50);
    CHECK(left.dir.y == Approx(0).margin(1e-12));
    CHECK(std::atan2(left.dir.x, left.dir.z) * 180 / kPi == Approx(-120));
    CHECK(std::atan2(quarter.dir.x, quarter.dir.z) * 180 / kPi == Approx(60));
    // Up: the height over the horizontal distance is straight in v, pixels square at the middle.
    const Ray top = camera.ray(200, 0);
    const double rise = top.dir.y / std::hypot(top.dir.x, top.dir.z);
    CHECK(rise == Approx(0.5 * 240 * kPi / 180 * 100 / 400));
    const Ray higher = camera.ray(300, 25);
    CHECK(higher.dir.y / std::hypot(higher.dir.x, higher.dir.z) == Approx(rise / 2));
}
