// Spheres resting exactly on planes: no acne next to the contact and no light leaking into it.
//
// The sphere touches the plane at one point, where the two surfaces are closer than any error
// bound. Each pixel that surely sees one surface (stress::coverage, against the analytic sphere
// and plane) must have its exact Lambert value C·(n·l) (ambient 0), or 0 where the analytic
// shadow ray is blocked; pixels whose shadow ray passes the sphere within rounding of its
// silhouette are not checked. The views are the whole scene from 15° above the plane and
// views into the crevice around the contact from nearly in the plane (see creviceView), where
// the gap between sphere and plane is 8·r·elevation². Three lights: from below the plane
// (nothing the camera sees may be lit at all), from behind the sphere (the crevice lies in its
// shadow: a lit pixel there is light leaking through) and grazing from the camera's side (the
// plane is lit right into the crevice: a dark pixel is acne).
#include "analytic_shapes.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;

namespace {

constexpr int kWidth = 96, kHeight = 72;
/// Lit pixels are C·(n·l) up to float storage (measured: 3e-8). An acne pixel is off by
/// C·(n·l) ≥ 8e-5 (the floor's smallest channel 0.4 under the grazing light 2e-4 rad above the
/// plane), a leak by up to the sphere's C.
constexpr double kTolerance = 1e-5;
/// Sphere pixels whose n·l is nearer 0 than this are not checked (its sign is uncertain).
constexpr double kMinCos = 0.01;
const scene::Color kFloor{0.4, 0.6, 0.8, 1};
const scene::Color kBall{0.9, 0.5, 0.4, 1};

/// A sphere of radius r resting on the plane through `contact` with unit normal n.
struct Contact {
    DVec3 normal;
    DVec3 contact;
    double radius;
    DVec3 center() const { return contact + radius * normal; }
};

enum class Surface { None, Ball, Floor };

struct Seen {
    Surface surface = Surface::None;
    SurfaceHit hit;
};

Seen nearest(const Contact& c, const TestRay& ray) {
    auto ball = sphereHit(ray, c.center(), c.radius);
    auto floor = planeHit(ray, c.normal, c.contact);
    if (ball && (!floor || ball->t <= floor->t)) return {Surface::Ball, *ball};
    if (floor) return {Surface::Floor, *floor};
    return {};
}

/// Counts of one rendered view.
struct ContactResult {
    int ball = 0, floorLit = 0, floorDark = 0, wrong = 0;
    double worst = 0;
    std::string firstWrong;
};

/// The expected value of a floor point, or nullopt where the shadow is uncertain.
std::optional<DVec3> floorValue(const Contact& c, DVec3 p, DVec3 toLight, ContactResult& counts) {
    double cosL = glm::dot(c.normal, toLight);
    if (cosL <= 0) { // a light below the floor
        ++counts.floorDark;
        return DVec3(0.0);
    }
    // The shadow ray's line passes the centre at `miss`. The renderer's shadow ray starts off
    // the surface by the hit point's error bound, a few roundings of the coordinates (also for
    // the nearly tangent camera rays of the crevice views), and the sphere's test of a line
    // near its silhouette rounds as much: a line passing the sphere within 1e-12 of them may
    // go either way (a shadow edge moved by that much is invisible).
    DVec3 f = p - c.center();
    double along = glm::dot(f, toLight);
    double miss = glm::length(f - along * toLight);
    double margin = 1e-12 * (c.radius + glm::length(c.contact));
    if (std::abs(miss - c.radius) < margin) return std::nullopt;
    bool shadowed = miss < c.radius && along < 0;
    ++(shadowed ? counts.floorDark : counts.floorLit);
    return shadowed ? DVec3(0.0) : test::rgbOf(kFloor) * cosL;
}

/// The expected value of pixel (x, y), or nullopt where it is not certain.
std::optional<DVec3> expected(const Contact& c, const scene::SceneDesc& desc, int x, int y,
                              DVec3 toLight, ContactResult& counts) {
    TestRay ray = test::specCameraRay(desc.camera, kWidth, kHeight, x, y);
    Seen seen = nearest(c, ray);
    auto same = [&](const TestRay& r) { return nearest(c, r).surface == seen.surface; };
    if (seen.surface == Surface::None || coverage(desc, x, y, 0.01, same) != Coverage::Inside)
        return std::nullopt;
    if (seen.surface == Surface::Floor) return floorValue(c, ray.at(seen.hit.t), toLight, counts);
    double cosL = glm::dot(seen.hit.normal, toLight);
    if (std::abs(cosL) < kMinCos) return std::nullopt;
    ++counts.ball;
    // The whole sphere is above the plane: a light below it reaches none of the sphere, a
    // light above it is never blocked by it.
    bool lightBelow = glm::dot(toLight, c.normal) < 0;
    return lightBelow ? DVec3(0.0) : test::rgbOf(kBall) * std::max(0.0, cosL);
}

ContactResult renderContact(const Contact& c, const scene::CameraDesc& camera, DVec3 toLight) {
    test::SceneMaker m;
    m.desc = test::blankScene(kWidth, kHeight, camera);
    m.draw(m.plane(c.normal, c.contact, lambertMaterial(m, kFloor)));
    m.draw(m.sphere(c.center(), c.radius, lambertMaterial(m, kBall)));
    m.desc.lights.push_back(parallelLight(toLight));
    PixelBuffer image = test::renderOk(m.desc);
    ContactResult result;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            std::optional<DVec3> want = expected(c, m.desc, x, y, toLight, result);
            if (!want) continue;
            DVec3 got = test::pixelAt(image, x, y);
            double d = test::maxDifference(got, *want);
            result.worst = std::max(result.worst, d);
            if (d > kTolerance && result.wrong++ == 0) {
                result.firstWrong = "pixel " + std::to_string(x) + "," + std::to_string(y) +
                                    " want " + number(want->x) + " got " + number(got.x);
            }
        }
    }
    return result;
}

/// The camera 4r from the contact, `elevation` radians above the plane.
DVec3 eyeAt(const Contact& c, double elevation) {
    DVec3 u, v;
    completeFrame(c.normal, u, v);
    return c.contact + 4 * c.radius * (std::sin(elevation) * c.normal - std::cos(elevation) * v);
}

/// A view into the crevice around the contact from `elevation` radians above the plane. Plane
/// points nearer the contact than 2r·elevation are hidden under the sphere, so the view is
/// aimed at the plane 4r·elevation from the contact, with a window four times the gap between
/// sphere and plane there.
scene::CameraDesc creviceView(const Contact& c, double elevation) {
    DVec3 u, v;
    completeFrame(c.normal, u, v);
    DVec3 target = c.contact - 4 * c.radius * elevation * v;
    return zoomedCamera(eyeAt(c, elevation), target, 32 * c.radius * elevation * elevation);
}

/// One view with the three lights; `grazing` is the elevation of the light from the camera's
/// side: a plane point at distance x from the contact sees past the sphere up to an elevation
/// of 2x/r, so at twice the view's elevation it lights every plane point the view shows.
void checkView(const Contact& c, const std::string& name, const scene::CameraDesc& camera,
               double grazing, bool belowOnly, std::string& summary) {
    DVec3 u, v;
    completeFrame(c.normal, u, v);
    const std::pair<const char*, DVec3> lights[] = {
        {"light below", glm::normalize(-c.normal + 0.5 * v + 0.1 * u)},
        {"light behind", glm::normalize(c.normal + 0.9 * v + 0.2 * u)},
        {"grazing light", glm::normalize(std::sin(grazing) * c.normal - std::cos(grazing) * v)}};
    for (const auto& [lightName, toLight] : lights) {
        if (belowOnly && toLight != lights[0].second) continue;
        ContactResult res = renderContact(c, camera, toLight);
        INFO(name << ", " << lightName << ": " << res.ball << " sphere pixels, " << res.floorLit
                  << " lit and " << res.floorDark << " dark floor pixels checked; " << res.wrong
                  << " differ from the expected value by more than " << kTolerance
                  << " (first: " << res.firstWrong << "), largest difference " << res.worst);
        CHECK(res.wrong == 0);
        CHECK(res.ball + res.floorLit + res.floorDark > kWidth * kHeight / 4);
        summary += name + ", " + lightName + ": " + std::to_string(res.ball) + " / " +
                   std::to_string(res.floorLit) + " / " + std::to_string(res.floorDark) +
                   ", worst " + number(res.worst) + "\n";
    }
}

/// The whole view and crevice views from the given elevations; `belowOnly`: only the light
/// from below the plane.
void checkContact(const Contact& c, const std::string& name, std::vector<double> elevations,
                  bool belowOnly = false) {
    std::string summary = name + " (sphere / lit floor / dark floor pixels checked):\n";
    auto whole = test::lookAt(eyeAt(c, 0.26), c.center() - 0.4 * c.radius * c.normal, 50);
    checkView(c, name + ", whole", whole, 0.05, belowOnly, summary);
    for (double e : elevations) {
        checkView(c, name + ", crevice from " + number(e) + " rad", creviceView(c, e), 2 * e,
                  belowOnly, summary);
    }
    WARN(summary);
}

} // namespace

TEST_CASE("A unit sphere resting on the plane y = 0", "[stress][contact]") {
    checkContact({DVec3(0, 1, 0), DVec3(0.0), 1}, "y = 0, radius 1", {1e-2, 1e-4});
}

TEST_CASE("A sphere resting on a tilted plane, at several scales", "[stress][contact]") {
    // The centre, contact + r·n, is rounded: the sphere touches the plane only to within the
    // rounding of its coordinates, as in any scene a user builds.
    const DVec3 n = glm::normalize(DVec3(0.3, 1, -0.2));
    for (double s : {1e-4, 1.0, 1e5}) {
        checkContact({n, s * DVec3(0.7, -0.1, 0.4), 1.3 * s}, "tilted, scale " + number(s),
                     {1e-2, 1e-4});
    }
}

TEST_CASE("A sphere resting on a plane 1e6 from the origin, seen from 1e-2 rad",
          "[stress][contact]") {
    const DVec3 n = glm::normalize(DVec3(-0.2, 1, 0.1));
    checkContact({n, DVec3(612345.678, -487654.321, 623456.789), 1}, "1e6 away", {1e-2});
}

// A shadow ray leaving a grazing camera hit starts off the surface by the hit point's error
// bound projected on the normal. That bound stands for the point's distance from the surface,
// not for the error along the nearly tangent camera ray (about 1/|n·d| times larger), which as
// an offset would exceed the gap near the contact and start shadow rays below the plane.
TEST_CASE("No light leaks into a sphere's contact with a plane seen from nearly in the plane",
          "[stress][contact]") {
    const DVec3 n = glm::normalize(DVec3(-0.2, 1, 0.1));
    checkContact({n, DVec3(0.0), 1}, "at the origin", {1e-5, 1e-6}, true);
    checkContact({n, DVec3(612345.678, -487654.321, 623456.789), 1}, "1e6 away", {1e-3, 1e-4},
                 true);
}
