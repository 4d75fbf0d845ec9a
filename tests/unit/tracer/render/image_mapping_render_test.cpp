// Render tests of image mappings: spherical and cylindrical images wrap around the shape's
// own centre and axis, so a shape made where it stands looks as the same shape made at the
// origin, upright, and moved there.
//
// The image is written by the test itself (tracer/image_io) into a scratch folder.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"
#include "../scratch_folder.hpp"
#include "tracer/image_io/image_io.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// A test card: red grows to the right, green downwards, blue in stripes across, so that
/// every part of the image has a colour of its own. Stored as raw codes (the scenes here
/// have gamma 1, so colours are read back as they were written).
std::string testCard() {
    static const std::string path = [] {
        setenv("CRT_IMAGE_IO_MODULE", CRT_TEST_IMAGE_IO_MODULE, 0);
        image_io::ImageBuffer image;
        image.width = 64;
        image.height = 32;
        image.pixels.resize(static_cast<size_t>(3 * image.width * image.height));
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                float* p = &image.pixels[static_cast<size_t>(3 * (y * image.width + x))];
                p[0] = static_cast<float>(x) / (image.width - 1);
                p[1] = static_cast<float>(y) / (image.height - 1);
                p[2] = static_cast<float>(0.5 + 0.5 * std::sin(2 * kTestPi * 3 * x / image.width));
            }
        std::string file = (scratch() / "card.png").string();
        std::string error;
        bool written = image_io::writeImage(file, image, image_io::WriteOptions{}, error);
        INFO(error);
        REQUIRE(written);
        return file;
    }();
    return path;
}

/// Renders one shape, textured with the test card through `mapping`, lit flat from the
/// camera with ambient light, against a black background.
PixelBuffer renderCard(const scene::CameraDesc& camera, const scene::Shape& shape,
                       const std::vector<scene::Modifier>& moves, scene::TextureMapping mapping) {
    SceneMaker m;
    m.desc = blankScene(64, 48, camera);
    scene::TextureDesc card;
    card.kind = scene::TextureKind::Image;
    card.file = card.resolvedFile = testCard();
    card.mapping = mapping;
    m.desc.textures.push_back(card);
    ShadingMaterial material;
    material.texture = static_cast<int32_t>(m.desc.textures.size() - 1);
    int32_t made = m.entity(shape, m.material(material));
    m.draw(moves.empty() ? made : m.transformed(made, moves));
    m.desc.settings.ambient = scene::Color{1, 1, 1, 1};
    return renderOk(m.desc);
}

/// Requires the shape made in place and the upright one moved there to look the same: within
/// 0.02 on 98% of the shape's pixels (rounding differs along the texels' edges), while the
/// card's colours spread over the shape.
void requireSameCard(const scene::CameraDesc& camera, const scene::Shape& inPlace,
                     const scene::Shape& upright, const std::vector<scene::Modifier>& moves,
                     scene::TextureMapping mapping) {
    PixelBuffer made = renderCard(camera, inPlace, {}, mapping);
    PixelBuffer moved = renderCard(camera, upright, moves, mapping);
    int shape = 0, close = 0;
    double redLow = 1, redHigh = 0, greenLow = 1, greenHigh = 0;
    for (int y = 0; y < made.height; ++y)
        for (int x = 0; x < made.width; ++x) {
            DVec3 a = pixelAt(made, x, y), b = pixelAt(moved, x, y);
            if (a == DVec3(0.0) && b == DVec3(0.0)) continue;
            ++shape;
            if (maxDifference(a, b) < 0.02) ++close;
            redLow = std::min(redLow, a.x), redHigh = std::max(redHigh, a.x);
            greenLow = std::min(greenLow, a.y), greenHigh = std::max(greenHigh, a.y);
        }
    INFO(close << " of " << shape << " pixels agree; red " << redLow << "…" << redHigh
               << ", green " << greenLow << "…" << greenHigh);
    REQUIRE(shape > 400);
    CHECK(close >= 0.98 * shape);
    // The card's colours spread over the shape (across it, or down it): it is not one colour.
    CHECK(std::max(redHigh - redLow, greenHigh - greenLow) > 0.3);
}

const scene::TextureMapping kAroundMappings[] = {scene::TextureMapping::Spherical,
                                                 scene::TextureMapping::Cylindrical};

} // namespace

TEST_CASE("A sphere made away from the origin is mapped as one made there and moved",
          "[render][texture]") {
    for (scene::TextureMapping mapping : kAroundMappings)
        requireSameCard(lookAt({0, 2.7, -4}, {0, 2.2, 0}, 40), scene::SphereShape{{0, 2.2, 0}, 1},
                        scene::SphereShape{{0, 0, 0}, 1}, {translate({0, 2.2, 0})}, mapping);
}

TEST_CASE("A cylinder and a cone along x are mapped about their own axis, as upright ones turned",
          "[render][texture]") {
    // rotate z −90 takes +y to +x: the upright shapes from the origin to (0, 2, 0) land on
    // the ones from (−1, 1, 0.5) to (1, 1, 0.5).
    std::vector<scene::Modifier> turn = {rotate({0, 0, -90}), translate({-1, 1, 0.5})};
    scene::CameraDesc camera = lookAt({0.5, 2.5, -4}, {0, 1, 0.5}, 45);
    for (scene::TextureMapping mapping : kAroundMappings) {
        requireSameCard(camera, scene::CylinderShape{{-1, 1, 0.5}, {1, 1, 0.5}, 0.7},
                        scene::CylinderShape{{0, 0, 0}, {0, 2, 0}, 0.7}, turn, mapping);
        requireSameCard(camera, scene::ConeShape{{-1, 1, 0.5}, 0.9, {1, 1, 0.5}, 0.3},
                        scene::ConeShape{{0, 0, 0}, 0.9, {0, 2, 0}, 0.3}, turn, mapping);
    }
}

TEST_CASE("A torus facing the camera is mapped about its centre and axis, as an upright one turned",
          "[render][texture]") {
    // rotate x −90 takes +y to −z, towards the camera.
    for (scene::TextureMapping mapping : kAroundMappings)
        requireSameCard(lookAt({0.5, 1, -4}, {0.5, 1, 0}, 45),
                        scene::TorusShape{{0.5, 1, 0}, 1, 0.35, {0, 0, -1}},
                        scene::TorusShape{{0, 0, 0}, 1, 0.35, {0, 1, 0}},
                        {rotate({-90, 0, 0}), translate({0.5, 1, 0})}, mapping);
}
