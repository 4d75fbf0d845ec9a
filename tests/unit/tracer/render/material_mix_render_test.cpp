// Render tests of materials made of others and of colours with alpha: a MaterialMap mixes
// its neighbours by the pattern's value, a Layered shows the layers under each alpha, and
// what the alphas leave passes the surface, unbent, in camera and shadow rays alike. Each
// checked pixel is recomputed from those rules; the scenes are lit flat (ambient 1, no
// lights), so that a pixel is its surface's colour.
#include "../scratch_folder.hpp"
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"
#include "tracer/image_io/image_io.hpp"

#include <cmath>
#include <cstdlib>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr double kTolerance = 1e-5;
constexpr int kW = 40, kH = 30;

int32_t flat(SceneMaker& m, scene::Color color, double filter = 0) {
    ShadingMaterial material;
    material.color = color;
    material.filter = filter;
    return m.material(material);
}

int32_t blend(SceneMaker& m, scene::BlendDesc blend) {
    m.desc.blends.push_back(std::move(blend));
    ShadingMaterial material;
    material.blend = static_cast<int32_t>(m.desc.blends.size() - 1);
    return m.material(material);
}

int32_t pattern(SceneMaker& m, scene::TextureKind kind) {
    m.desc.textures.push_back(scene::defaultTexture(kind));
    return static_cast<int32_t>(m.desc.textures.size() - 1);
}

/// A flat-lit scene looking at the wall z = 0 around x = 0.5, y = 0.5 (x and y within
/// 0.1 … 0.9 on screen), with a grey background.
SceneMaker wallScene() {
    SceneMaker m;
    m.desc = blankScene(kW, kH, lookAt({0.5, 0.5, -10}, {0.5, 0.5, 0}, 4));
    m.desc.settings.ambient = scene::Color{1, 1, 1, 1};
    m.desc.background.color = scene::Color{0.3, 0.3, 0.3, 1};
    return m;
}

/// Checks every pixel against want(point on the wall); returns how many it checked.
template <typename Want> int checkWall(const SceneMaker& m, Want want) {
    PixelBuffer image = renderOk(m.desc);
    int checked = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, kW, kH, x, y);
            std::optional<double> t = hitPlane(ray, {0, 0, -1}, {0, 0, 0});
            REQUIRE(t);
            DVec3 point = ray.origin + *t * ray.dir;
            DVec3 got = pixelAt(image, x, y), expected = want(point);
            INFO("pixel " << x << "," << y << " got " << got.x << " " << got.y << " " << got.z
                          << " want " << expected.x << " " << expected.y << " " << expected.z);
            CHECK(maxDifference(got, expected) < kTolerance);
            ++checked;
        }
    }
    return checked;
}

const scene::Color kRed{0.9, 0.1, 0.1, 1}, kBlue{0.1, 0.2, 0.9, 1};
const DVec3 kBackground(0.3);

} // namespace

TEST_CASE("A MaterialMap mixes the two materials around the pattern's value", "[render][mix]") {
    SceneMaker m = wallScene();
    scene::BlendDesc map;
    map.pattern = pattern(m, scene::TextureKind::Gradient); // value: x's fraction
    map.values = {0.3, 0.7};
    map.materials = {flat(m, kRed), flat(m, kBlue)};
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, blend(m, map)));
    int checked = checkWall(m, [](DVec3 p) {
        double f = std::clamp((p.x - 0.3) / 0.4, 0.0, 1.0);
        return (1 - f) * rgbOf(kRed) + f * rgbOf(kBlue);
    });
    CHECK(checked == kW * kH);
}

TEST_CASE("A MaterialMap of a discrete pattern picks its materials by position", "[render][mix]") {
    // The same wall with the pattern's colours instead: the two images agree.
    SceneMaker colours = wallScene();
    ShadingMaterial textured;
    textured.texture = pattern(colours, scene::TextureKind::Checker);
    colours.desc.textures.back().colors = {{0, kRed}, {1, kBlue}};
    colours.desc.textures.back().modifiers = {scale({0.25, 0.25, 0.25})};
    colours.draw(colours.plane({0, 0, -1}, {0, 0, 0}, colours.material(textured)));
    PixelBuffer want = renderOk(colours.desc);

    SceneMaker m = wallScene();
    scene::BlendDesc map;
    map.pattern = pattern(m, scene::TextureKind::Checker);
    m.desc.textures.back().modifiers = {scale({0.25, 0.25, 0.25})};
    map.values = {0, 1};
    map.materials = {flat(m, kRed), flat(m, kBlue)};
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, blend(m, map)));
    PixelBuffer got = renderOk(m.desc);
    CHECK(got.pixels == want.pixels);
    int reds = 0;
    for (int y = 0; y < kH; ++y) reds += pixelAt(got, kW / 2, y).x > 0.5;
    CHECK(reds > 0);
    CHECK(reds < kH); // both materials are seen
}

TEST_CASE("A Layered shows the layers under each layer's alpha, and the background through all",
          "[render][mix]") {
    SceneMaker m = wallScene();
    scene::BlendDesc layers;
    layers.kind = scene::BlendKind::Layers;
    scene::Color halfBlue = kBlue, quarterRed = kRed;
    halfBlue.a = 0.5;
    quarterRed.a = 0.25;
    layers.materials = {flat(m, halfBlue), flat(m, quarterRed)};
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, blend(m, layers)));
    int checked = checkWall(m, [](DVec3) {
        return 0.25 * rgbOf(kRed) + 0.75 * 0.5 * rgbOf(kBlue) + 0.75 * 0.5 * kBackground;
    });
    CHECK(checked == kW * kH);
}

TEST_CASE("What alpha lets through takes the surface's colour by filter", "[render][mix]") {
    for (double filter : {0.0, 0.4, 1.0}) {
        INFO("filter " << filter);
        SceneMaker m = wallScene();
        scene::Color lace = kRed;
        lace.a = 0.3;
        m.draw(m.plane({0, 0, -1}, {0, 0, 0}, flat(m, lace, filter)));
        checkWall(m, [&](DVec3) {
            DVec3 passes = 0.7 * ((1 - filter) * DVec3(1.0) + filter * rgbOf(kRed));
            return 0.3 * rgbOf(kRed) + passes * kBackground;
        });
    }
}

TEST_CASE("A colour map's alpha cuts the surface where the pattern says", "[render][mix]") {
    SceneMaker m = wallScene();
    ShadingMaterial fence;
    fence.texture = pattern(m, scene::TextureKind::Gradient);
    m.desc.textures.back().colors = {{0.5, kRed}, {0.5, scene::Color{0, 0, 0, 0}}};
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, m.material(fence)));
    int checked = checkWall(m, [](DVec3 p) { return p.x <= 0.5 ? rgbOf(kRed) : kBackground; });
    CHECK(checked == kW * kH);
}

TEST_CASE("Shadows pass a surface by its alpha, tinted by filter", "[render][mix]") {
    // A white floor lit straight down, under a sheet of alpha 0.4 above the camera.
    SceneMaker m;
    m.desc = blankScene(kW, kH, lookAt({0, 0.5, -4}, {0, 0, 0}, 40));
    m.desc.lights.push_back(parallelLight({0, 10, 0}));
    scene::Color sheet = kRed;
    sheet.a = 0.4;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.colored(1, 1, 1)));
    m.draw(m.plane({0, -1, 0}, {0, 2, 0}, flat(m, sheet, 0.5)));
    PixelBuffer image = renderOk(m.desc);
    DVec3 want = 0.6 * (0.5 * DVec3(1.0) + 0.5 * rgbOf(kRed));
    int checked = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, kW, kH, x, y);
            if (!hitPlane(ray, {0, 1, 0}, {0, 0, 0})) continue;
            CHECK(maxDifference(pixelAt(image, x, y), want) < kTolerance);
            ++checked;
        }
    }
    CHECK(checked > kW * kH / 3);
}

TEST_CASE("An image's alpha channel cuts the surface", "[render][mix]") {
    // Eight texels across the wall: the left four transparent, the right four red. Where a
    // lookup mixes the two halves the pixel is left out.
    setenv("CRT_IMAGE_IO_MODULE", CRT_TEST_IMAGE_IO_MODULE, 0);
    image_io::ImageBuffer leaf{8, 1, 4, {}};
    for (int x = 0; x < 8; ++x)
        leaf.pixels.insert(leaf.pixels.end(), {1, 0, 0, x < 4 ? 0.0f : 1.0f});
    std::string path = (scratch() / "leaf.png").string(), error;
    INFO(error);
    REQUIRE(image_io::writeImage(path, leaf, image_io::WriteOptions{}, error));

    SceneMaker m = wallScene();
    scene::TextureDesc image = scene::defaultTexture(scene::TextureKind::Image);
    image.file = image.resolvedFile = path;
    image.mapping = scene::TextureMapping::Planar;
    m.desc.textures.push_back(image);
    ShadingMaterial cutOut;
    cutOut.texture = 0;
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, m.material(cutOut)));
    PixelBuffer picture = renderOk(m.desc);
    int clear = 0, solid = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            TestRay ray = specCameraRay(m.desc.camera, kW, kH, x, y);
            double u = (ray.origin + *hitPlane(ray, {0, 0, -1}, {0, 0, 0}) * ray.dir).x;
            DVec3 got = pixelAt(picture, x, y);
            if (u > 3.0 / 16 && u < 7.0 / 16) {
                CHECK(maxDifference(got, kBackground) < kTolerance);
                ++clear;
            } else if (u > 9.0 / 16 && u < 13.0 / 16) {
                CHECK(maxDifference(got, DVec3(1, 0, 0)) < kTolerance);
                ++solid;
            }
        }
    }
    CHECK(clear > kH * 5);
    CHECK(solid > kH * 5);
}
