// Render tests of glossy transmission (frosted glass): a glass sphere's glossiness blurs what
// is seen through it, and at glossiness 0 refraction stays the sharp path of Snell's law.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 64;
const DVec3 kCenter(0, 0, 0);
constexpr double kRadius = 1, kIor = 1.5;
// The checker wall z = 1.35 (mid-cell in z), inside the ball lens's focal length: seen through
// the glass its cells are magnified to about six pixels.
constexpr double kWall = 1.35, kCell = 0.1;
constexpr int kBlock = 4; // contrast is measured between means of 4×4 pixel blocks

scene::CameraDesc camera() {
    return lookAt({0, 0, -5}, {0, 0, 0}, 30);
}

/// A glass sphere (no diffuse light of its own, no Fresnel) in front of a black and white
/// checker wall lit by ambient light alone, so a pixel seen through the glass is exactly the
/// wall's colour where its ray arrives.
scene::SceneDesc glassInFrontOfChecker(double glossiness, int glossySamples) {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, camera());
    m.desc.settings.ambient = scene::Color{1, 1, 1, 1};
    m.desc.settings.glossySamples = glossySamples;
    m.desc.settings.recursionDepth = 6; // rays reflected inside the glass get out again
    scene::TextureDesc checker;
    checker.kind = scene::TextureKind::Checker;
    checker.colors = {{0, {1, 1, 1, 1}}, {1, {0, 0, 0, 1}}};
    checker.size = kCell;
    m.desc.textures.push_back(checker);
    ShadingMaterial wall;
    wall.texture = 0;
    m.draw(m.plane({0, 0, -1}, {0, 0, kWall}, m.material(wall)));
    ShadingMaterial glass;
    glass.color = scene::Color{1, 1, 1, 1};
    glass.transparency = 1;
    glass.diffuse = 0;
    glass.ior = kIor;
    glass.glossiness = glossiness;
    m.draw(m.sphere(kCenter, kRadius, m.material(glass)));
    return m.desc;
}

/// Whether the pixel's camera ray crosses the sphere well inside its silhouette.
bool throughGlass(int x, int y) {
    return hitSphere(specCameraRay(camera(), kSize, kSize, x, y), kCenter, kRadius, 0.05)
        .has_value();
}

/// The grey level seen through the glass, in blocks of kBlock × kBlock pixels: averaging a
/// block takes out most of the noise of a finite number of glossy samples, while a sharp
/// pattern of cells about as large as a block still varies between blocks.
struct Sharpness {
    int blocks = 0;
    double mean = 0;     ///< of the blocks' means
    double contrast = 0; ///< standard deviation of the blocks' means
};

Sharpness sharpness(const PixelBuffer& image) {
    Sharpness s;
    double sum = 0, squares = 0;
    for (int by = 0; by < kSize; by += kBlock) {
        for (int bx = 0; bx < kSize; bx += kBlock) {
            double block = 0;
            bool inside = true;
            for (int y = by; y < by + kBlock; ++y)
                for (int x = bx; x < bx + kBlock; ++x) {
                    inside = inside && throughGlass(x, y);
                    block += pixelAt(image, x, y).x;
                }
            if (!inside) continue;
            block /= kBlock * kBlock;
            ++s.blocks;
            sum += block;
            squares += block * block;
        }
    }
    if (s.blocks == 0) return s;
    s.mean = sum / s.blocks;
    s.contrast = std::sqrt(std::max(0.0, squares / s.blocks - s.mean * s.mean));
    return s;
}

/// The wall's colour where a camera ray arrives after refracting into and out of the sphere
/// (Snell's law at both surfaces), or nullopt within `margin` of a cell edge.
std::optional<double> sharpWallSeen(const TestRay& ray, double margin) {
    auto tIn = hitSphere(ray, kCenter, kRadius);
    if (!tIn) return std::nullopt;
    DVec3 p = ray.at(*tIn);
    auto inside = snellRefract(ray.dir, (p - kCenter) / kRadius, 1, kIor);
    if (!inside) return std::nullopt;
    // Leaving: the far root of the line's crossings with the sphere.
    DVec3 f = p - kCenter;
    double b = glm::dot(f, *inside);
    double tOut = -b + std::sqrt(b * b - (glm::dot(f, f) - kRadius * kRadius));
    DVec3 q = p + tOut * *inside;
    auto outside = snellRefract(*inside, -(q - kCenter) / kRadius, kIor, 1);
    if (!outside) return std::nullopt;
    auto tWall = hitPlane({q, *outside}, {0, 0, -1}, {0, 0, kWall});
    if (!tWall) return std::nullopt;
    DVec3 w = q + *tWall * *outside;
    for (double c : {w.x, w.y}) {
        double inCell = c / kCell - std::floor(c / kCell);
        if (inCell < margin / kCell || inCell > 1 - margin / kCell) return std::nullopt;
    }
    long parity = static_cast<long>(std::floor(w.x / kCell)) +
                  static_cast<long>(std::floor(w.y / kCell)) +
                  static_cast<long>(std::floor(w.z / kCell));
    return (parity & 1) ? 0.0 : 1.0;
}

} // namespace

TEST_CASE("Glass of glossiness 0 refracts sharply, whatever glossysamples is", "[render][glossy]") {
    PixelBuffer sharp = renderOk(glassInFrontOfChecker(0, 16));
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!throughGlass(x, y)) continue;
            auto want = sharpWallSeen(specCameraRay(camera(), kSize, kSize, x, y), 0.005);
            if (!want) continue;
            INFO("pixel " << x << "," << y);
            CHECK(std::abs(pixelAt(sharp, x, y).x - *want) < 1e-4);
            ++checked;
        }
    }
    CHECK(checked > 300);
    // The glossy samples are not drawn at all: the same bits with one sample or sixteen.
    CHECK(renderOk(glassInFrontOfChecker(0, 1)).pixels == sharp.pixels);
}

TEST_CASE("Frosted glass blurs what is seen through it, keeping its brightness",
          "[render][glossy]") {
    Sharpness sharp = sharpness(renderOk(glassInFrontOfChecker(0, 16)));
    PixelBuffer frostedImage = renderOk(glassInFrontOfChecker(0.4, 64));
    Sharpness frosted = sharpness(frostedImage);
    INFO("contrast " << sharp.contrast << " sharp, " << frosted.contrast << " frosted; mean "
                     << sharp.mean << " sharp, " << frosted.mean << " frosted, over "
                     << sharp.blocks << " blocks");
    REQUIRE(sharp.blocks > 60);
    CHECK(sharp.contrast > 0.25); // the checker is seen clearly through clear glass
    CHECK(frosted.contrast < 0.25 * sharp.contrast);
    // Blurring averages the wall; it neither darkens nor brightens it on the whole.
    CHECK(std::abs(frosted.mean - sharp.mean) < 0.1);
    // Every sample's directions come from (seed, pixel, sample): the same bits on one thread.
    CHECK(renderOk(glassInFrontOfChecker(0.4, 64), 1).pixels == frostedImage.pixels);
}
