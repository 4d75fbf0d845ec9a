// Analytic render tests of spawned rays (spec §6): mirrors, recursion depth, Snell refraction
// through a slab, total internal reflection, Fresnel and Beer–Lambert absorption.
//
// Light sources here are emissive surfaces seen through the optics (no lights), so a pixel is
// exactly the emission or background colour times the spec's factors. Paths are traced in the
// test itself; pixels whose analytic path passes within a small distance of an edge are skipped.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

ShadingMaterial emissive(scene::Color e) {
    ShadingMaterial m;
    m.color = scene::Color{0, 0, 0, 1};
    m.diffuse = 0;
    m.emission = e;
    return m;
}

ShadingMaterial glass(double ior, double transparency = 1) {
    ShadingMaterial m;
    m.color = scene::Color{1, 1, 1, 1};
    m.transparency = transparency;
    m.diffuse = 0;
    m.ior = ior;
    return m;
}

/// The pixel as stored: the renderer computes in doubles and stores floats.
DVec3 asStored(DVec3 c) { return {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)}; }

} // namespace

TEST_CASE("A mirror reflects a known colour exactly and recursion depth 0 gives no reflection", "[render][analytic]") {
    const int W = 64, H = 48;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0.3, 0.2, -5}, {0, 0, 0}, 40));
    const scene::Color background{0.9, 0.1, 0.2, 1};
    const scene::Color E{0.3, 0.5, 0.7, 1};
    m.desc.background.color = background;
    ShadingMaterial mirror;
    mirror.color = scene::Color{0.25, 0.25, 0.25, 1}; // not metallic: reflections are untinted (K = white)
    mirror.reflectivity = 1;
    mirror.diffuse = 0;
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, m.material(mirror)));
    // An emissive sheet behind the camera covering y > 0.3 at z = −11; below it the background shows.
    const double wallZ = -11, wallY = 0.3;
    m.draw(m.entity(scene::QuadShape{{-100, wallY, wallZ}, {200, 0, 0}, {0, 100, 0}}, m.material(emissive(E)), false));

    auto expectedAt = [&](int x, int y, bool& skip) {
        TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
        auto t = hitPlane(ray, {0, 0, -1}, {0, 0, 0});
        REQUIRE(t);
        DVec3 p = ray.at(*t);
        DVec3 r(ray.dir.x, ray.dir.y, -ray.dir.z); // mirrored about the plane z = 0
        double yAtWall = p.y + r.y * (wallZ - p.z) / r.z;
        skip = std::abs(yAtWall - wallY) < 0.02;
        return yAtWall > wallY ? rgbOf(E) : rgbOf(background);
    };

    SECTION("depth 1: every pixel is exactly the reflected emission or background") {
        m.desc.settings.recursionDepth = 1;
        PixelBuffer image = renderOk(m.desc);
        int sheet = 0, sky = 0;
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                bool skip = false;
                DVec3 want = expectedAt(x, y, skip);
                if (skip) continue;
                INFO("pixel " << x << "," << y);
                CHECK(pixelAt(image, x, y) == asStored(want));
                (want == rgbOf(E) ? sheet : sky)++;
            }
        }
        CHECK(sheet > 200);
        CHECK(sky > 200);
    }
    SECTION("depth 0: no reflection ray, a black mirror (diffuse 0, no lights)") {
        m.desc.settings.recursionDepth = 0;
        PixelBuffer image = renderOk(m.desc);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                INFO("pixel " << x << "," << y);
                CHECK(pixelAt(image, x, y) == DVec3(0.0));
            }
    }
}

namespace {

/// A glass slab between the planes z = 0 and z = thickness, seen by an oblique camera.
struct SlabPath {
    DVec3 entry, exit; ///< where the ray enters and leaves the slab
    DVec3 inside;      ///< direction inside
    DVec3 after;       ///< direction after the slab
};

SlabPath traceSlab(const TestRay& ray, double thickness, double ior) {
    SlabPath path;
    auto t = hitPlane(ray, {0, 0, -1}, {0, 0, 0});
    REQUIRE(t);
    path.entry = ray.at(*t);
    auto in = snellRefract(ray.dir, {0, 0, -1}, 1.0, ior);
    REQUIRE(in);
    path.inside = *in;
    path.exit = path.entry + path.inside * (thickness / path.inside.z);
    auto out = snellRefract(path.inside, {0, 0, -1}, ior, 1.0);
    REQUIRE(out);
    path.after = *out;
    return path;
}

} // namespace

TEST_CASE("Refraction through a glass slab shifts a stripe pattern by what Snell's law gives", "[render][analytic]") {
    const int W = 96, H = 72;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({-1.5, 0.3, -5}, {0.5, 0, 2}, 30));
    // Ambient light 1 shows the wall's texture colour unshaded; the slab has no diffuse part.
    m.desc.settings.ambient = scene::Color{1, 1, 1, 1};
    const double thickness = 1, ior = 1.5, wallZ = 3, stripe = 0.25;
    m.draw(m.box({-20, -20, 0}, {20, 20, thickness}, m.material(glass(ior))));
    scene::TextureDesc stripes;
    stripes.kind = scene::TextureKind::Stripes;
    stripes.colors = {{0, {1, 1, 0, 1}}, {1, {0, 0.2, 1, 1}}};
    stripes.size = stripe;
    stripes.axis = {1, 0, 0};
    m.desc.textures.push_back(stripes);
    ShadingMaterial wall;
    wall.texture = 0;
    m.draw(m.plane({0, 0, -1}, {0, 0, wallZ}, m.material(wall)));
    PixelBuffer image = renderOk(m.desc);

    int checked = 0, shifted = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            SlabPath path = traceSlab(ray, thickness, ior);
            // A slab's faces are parallel, so the ray leaves in its original direction, displaced.
            REQUIRE(glm::length(path.after - ray.dir) < 1e-12);
            double wallX = path.exit.x + path.after.x * (wallZ - thickness) / path.after.z;
            double cell = wallX / stripe;
            if (std::abs(fract(cell) - 0.5) > 0.5 - 0.02) continue; // too near a stripe boundary
            bool odd = static_cast<long>(std::floor(cell)) & 1;
            DVec3 want = rgbOf(stripes.colors[odd ? 1 : 0].color);
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " wall x " << wallX << " got " << got.x << " " << got.y << " " << got.z);
            CHECK(maxDifference(got, want) < 1e-6);
            ++checked;
            // Where the unrefracted line would land, for a check that the shift matters.
            double straightX = ray.origin.x + ray.dir.x * (wallZ - ray.origin.z) / ray.dir.z;
            shifted += static_cast<long>(std::floor(straightX / stripe)) != static_cast<long>(std::floor(cell));
        }
    }
    CHECK(checked > W * H * 3 / 4);
    CHECK(shifted > checked / 6);
}

TEST_CASE("Beer-Lambert absorption through a slab is exp(-a d) over the refracted path", "[render][analytic]") {
    const int W = 48, H = 36;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({-1, 0.5, -4}, {0.3, 0, 1}, 40));
    const scene::Color background{0.9, 0.8, 0.7, 1};
    m.desc.background.color = background;
    const double thickness = 2, ior = 1.5;
    const DVec3 a(0.3, 0.8, 1.5);
    ShadingMaterial tinted = glass(ior);
    tinted.absorption = scene::Color{a.x, a.y, a.z, 1};
    m.draw(m.box({-50, -50, 0}, {50, 50, thickness}, m.material(tinted)));
    PixelBuffer image = renderOk(m.desc);

    double shortest = 1e9, longest = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            SlabPath path = traceSlab(specCameraRay(m.desc.camera, W, H, x, y), thickness, ior);
            double d = glm::length(path.exit - path.entry);
            DVec3 want = rgbOf(background) * glm::exp(-a * d);
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " path inside " << d);
            CHECK(maxDifference(got, want) < 1e-6);
            shortest = std::min(shortest, d);
            longest = std::max(longest, d);
        }
    }
    CHECK(longest > shortest * 1.02); // oblique rays travel measurably further inside
}

TEST_CASE("Total internal reflection in a 45-degree prism sends the view sideways", "[render][analytic]") {
    const int W = 40, H = 40;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0, 0, -6}, {0, 0, 0}, 8));
    m.desc.background.color = scene::Color{0.5, 0.5, 0.5, 1};
    const double ior = 1.6; // critical angle 38.7°; inside, the diagonal is met at 45° ± 4°
    int32_t glassMaterial = m.material(glass(ior));
    // The cube [-1, 1]³ cut by the plane z = x, keeping z ≤ x (the half-space behind (−1, 0, 1)).
    int32_t cube = m.box({-1, -1, -1}, {1, 1, 1}, glassMaterial);
    int32_t half = m.plane({-1, 0, 1}, {0, 0, 0}, glassMaterial);
    m.draw(m.csg(scene::CsgOp::Intersection, cube, half));
    const scene::Color side{0.2, 0.9, 0.3, 1}, behind{0.9, 0.2, 0.2, 1};
    const double sideX = 4, behindZ = 6;
    m.draw(m.entity(scene::QuadShape{{sideX, -50, -50}, {0, 100, 0}, {0, 0, 100}}, m.material(emissive(side)), false));
    m.draw(m.entity(scene::QuadShape{{-50, -50, behindZ}, {100, 0, 0}, {0, 100, 0}}, m.material(emissive(behind)), false));
    PixelBuffer image = renderOk(m.desc);

    const DVec3 diagonalOutward = glm::normalize(DVec3(-1, 0, 1));
    int checked = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            auto t = hitPlane(ray, {0, 0, -1}, {0, 0, -1});
            REQUIRE(t);
            DVec3 p = ray.at(*t);
            REQUIRE((std::abs(p.x) < 0.5 && std::abs(p.y) < 0.5));
            auto in = snellRefract(ray.dir, {0, 0, -1}, 1.0, ior);
            REQUIRE(in);
            // Inside: to the diagonal face, where the ray must be totally reflected.
            TestRay inside{p, *in};
            auto tDiag = hitPlane(inside, diagonalOutward, {0, 0, 0});
            REQUIRE(tDiag);
            DVec3 q = inside.at(*tDiag);
            REQUIRE_FALSE(snellRefract(inside.dir, -diagonalOutward, ior, 1.0));
            DVec3 r = inside.dir - 2 * glm::dot(inside.dir, diagonalOutward) * diagonalOutward;
            // Out through the face x = 1, then to the side sheet.
            TestRay reflected{q, r};
            auto tSide = hitPlane(reflected, {1, 0, 0}, {1, 0, 0});
            REQUIRE(tSide);
            DVec3 s = reflected.at(*tSide);
            REQUIRE((std::abs(s.y) < 1 && s.z > -1 && s.z < 1));
            auto out = snellRefract(r, {-1, 0, 0}, ior, 1.0);
            REQUIRE(out);
            REQUIRE(out->x > 0);
            INFO("pixel " << x << "," << y);
            CHECK(pixelAt(image, x, y) == asStored(rgbOf(side)));
            ++checked;
        }
    }
    CHECK(checked == W * H);
}

TEST_CASE("Fresnel moves kt*F into reflection: kr' = kr + kt F, kt' = kt (1 - F)", "[render][analytic]") {
    const int W = 64, H = 48;
    SceneMaker m;
    m.desc = blankScene(W, H, lookAt({0, 1, 0}, {0, 0, 2}, 40));
    const scene::Color background{0.1, 0.3, 0.05, 1};
    const scene::Color sky{0.8, 0.9, 1.0, 1};
    m.desc.background.color = background;
    const double kr = 0.2, kt = 0.8, ior = 1.5;
    // A glass half-space y ≤ 0: the refracted ray never leaves it and sees the background.
    ShadingMaterial water = glass(ior, kt);
    water.reflectivity = kr;
    water.fresnel = true;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(water)));
    // The reflected ray sees an emissive ceiling.
    m.draw(m.entity(scene::QuadShape{{-200, 5, -200}, {400, 0, 0}, {0, 0, 400}}, m.material(emissive(sky)), false));
    PixelBuffer image = renderOk(m.desc);

    double lowestF = 1, highestF = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, W, H, x, y);
            REQUIRE(ray.dir.y < 0);
            double F = fresnelReflectance(-ray.dir.y, 1.0, ior);
            DVec3 want = (kr + kt * F) * rgbOf(sky) + kt * (1 - F) * rgbOf(background);
            DVec3 got = pixelAt(image, x, y);
            INFO("pixel " << x << "," << y << " F " << F << " got " << got.x << " " << got.y << " " << got.z);
            CHECK(maxDifference(got, want) < 1e-6);
            lowestF = std::min(lowestF, F);
            highestF = std::max(highestF, F);
        }
    }
    CHECK(highestF > 3 * lowestF); // grazing rays reflect far more than steep ones
}
