// Caustics under the path integrator: light reaching a surface through clear glass, solved
// for by light sampling (tracer/path_caustics.cpp), against closed forms and against the
// paths' own bounces.
#include "path_scene_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = kPathImageSize;

/// Clear glass letting `transparency` through, without Fresnel's share of reflection;
/// `glossiness` above 0 frosts it.
ShadingMaterial glass(double transparency, double ior, double glossiness = 0) {
    ShadingMaterial m;
    m.color = scene::Color{1, 1, 1, 1};
    m.diffuse = 0;
    m.transparency = transparency;
    m.ior = ior;
    m.glossiness = glossiness;
    return m;
}

scene::LightDesc pointLight(glm::dvec3 origin, double color) {
    scene::LightDesc light;
    light.kind = scene::LightKind::Point;
    light.origin = origin;
    light.color = scene::Color{color, color, color, 1};
    return light;
}

/// The mean of the images' red channel and its standard error, and the noise of one
/// image's pixels (root mean square), from two renders of other seeds: their difference is
/// noise alone, whatever the light's shape across the image.
struct Estimate {
    double mean = 0, standardError = 0, pixelNoise = 0;
};

Estimate estimate(const PixelBuffer& a, const PixelBuffer& b) {
    double sum = 0, variance = 0;
    const int n = kSize * kSize;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double va = pixelAt(a, x, y).x, vb = pixelAt(b, x, y).x;
            sum += va + vb;
            variance += (va - vb) * (va - vb) / 2; // a pixel's, in one image
        }
    // The mean of both images: each pixel's variance halved, summed over n pixels, over n².
    return {sum / (2 * n), std::sqrt(variance / 2) / n, std::sqrt(variance / n)};
}

} // namespace

TEST_CASE("path: a point light lights the floor through a clear sheet by the share the sheet lets through",
          "[render][path][caustics]") {
    // A tilted sheet (a disc without inside) bends nothing: the floor's centre gets
    // ρ·L·cos θ times its transparency. Light sampling's straight shadow ray is stopped by
    // the sheet, so this is the solved path's light alone: its spread must come out as the
    // square of the distance.
    constexpr double kAlbedo = 0.5, kLight = 2, kTransparency = 0.6;
    SceneMaker m = floorSeenFromAbove(4, 3, kAlbedo);
    m.draw(m.entity(scene::DiscShape{{0.2, 2, 0.1}, glm::normalize(glm::dvec3(0.3, 1, -0.2)), 1.5},
                    m.material(glass(kTransparency, 1.5)), false));
    const glm::dvec3 lamp{0.6, 4, 0.3};
    m.desc.lights.push_back(pointLight(lamp, kLight));
    const PixelBuffer image = renderOk(m.desc);
    const double expected = kAlbedo * kLight * kTransparency * lamp.y / glm::length(lamp);
    CHECK(std::abs(pixelAt(image, kSize / 2, kSize / 2).x - expected) < 1e-4 * expected);
}

TEST_CASE("path: a point light lights the floor through a glass slab as from its apparent distance",
          "[render][path][caustics]") {
    // A slab of thickness t and index n between the floor and a light h above it: the beam
    // from the floor's centre spreads as if the light were h − t + t/n away, while the path
    // is h long. The light has no falloff, so the floor gets ρ·L·(h / (h − t + t/n))².
    constexpr double kAlbedo = 0.5, kLight = 1, kHeight = 4, kThickness = 1, kIor = 1.5;
    SceneMaker m = floorSeenFromAbove(4, 3, kAlbedo);
    m.draw(m.box({-5, 1.5, -5}, {5, 1.5 + kThickness, 5}, m.material(glass(1, kIor))));
    m.desc.lights.push_back(pointLight({0, kHeight, 0}, kLight));
    const PixelBuffer image = renderOk(m.desc);
    const double apparent = kHeight - kThickness + kThickness / kIor;
    const double expected = kAlbedo * kLight * (kHeight / apparent) * (kHeight / apparent);
    CHECK(std::abs(pixelAt(image, kSize / 2, kSize / 2).x - expected) < 1e-4 * expected);
}

/// The floor under a glass ball frosted by `glossiness` (0: clear), lit by what `light`
/// adds above it, seen from straight above: the estimate of two renders of `samples` paths.
template <typename AddLight>
Estimate floorUnderBall(double glossiness, int samples, AddLight&& light) {
    SceneMaker m = floorSeenFromAbove(samples, 3, 0.8);
    m.desc.camera = lookAt({0, 0.5, 0}, {0, 0, 0}, 40);
    m.desc.camera.up = {0, 0, 1};
    ShadingMaterial ball = glass(1, 1.5, glossiness);
    ball.fresnel = true;
    m.draw(m.sphere({0, 1.5, 0}, 0.5, m.material(ball)));
    light(m);
    const PixelBuffer first = renderOk(m.desc);
    m.desc.settings.seed = 2;
    return estimate(first, renderOk(m.desc));
}

/// The solved image's light is the bounces' own within their noise, and it has far less
/// noise.
void checkSameLightLessNoise(const Estimate& solved, const Estimate& bounced) {
    INFO("solved " << solved.mean << " ± " << solved.standardError << " (pixels ± " << solved.pixelNoise
                   << "), bounces alone " << bounced.mean << " ± " << bounced.standardError << " (pixels ± "
                   << bounced.pixelNoise << ")");
    CHECK(std::abs(solved.mean - bounced.mean) <=
          3 * std::hypot(solved.standardError, bounced.standardError) + 1e-4 * bounced.mean);
    CHECK(solved.pixelNoise < bounced.pixelNoise / 4);
}

TEST_CASE("path: the caustic of a glass ball under a glowing disc is the bounces' own, with less noise",
          "[render][path][caustics]") {
    // The floor under a glass ball, lit by a small glowing disc above it: light sampling
    // solves for the paths through the ball, and the bounces' paths that light sampling also
    // reaches are weighed against it. Frosting the glass by 10⁻⁹ leaves the light as it is
    // but makes it the bounces' alone: the two images must agree within their noise, and
    // the solved one must have far less of it.
    const auto disc = [](SceneMaker& m) {
        m.draw(m.entity(scene::DiscShape{{0, 4, 0}, {0, -1, 0}, 0.3}, m.material(diffuse(0, 20)), false));
    };
    checkSameLightLessNoise(floorUnderBall(0, 64, disc), floorUnderBall(1e-9, 256, disc));
}

TEST_CASE("path: the caustic of a glass ball under an area light is the bounces' own, with less noise",
          "[render][path][caustics]") {
    // As under the glowing disc, with an AreaLight: light sampling solves for the paths from
    // the floor through the ball to the point it drew on the light, each point lighting as a
    // point light does through glass; the bounces that meet the light through the ball carry
    // the radiance that gives the same light, and the two are weighed against each other.
    const auto lamp = [](SceneMaker& m) { m.desc.lights.push_back(areaLight(0.5, 4, 1)); };
    checkSameLightLessNoise(floorUnderBall(0, 64, lamp), floorUnderBall(1e-9, 1024, lamp));
}

TEST_CASE("path: caustics give the same bits on any number of threads", "[render][path][caustics]") {
    SceneMaker m = floorSeenFromAbove(8, 4, 0.7);
    m.desc.camera = lookAt({0, 2, -3}, {0, 0.4, 0}, 50);
    m.draw(m.sphere({0, 0.6, 0}, 0.6, m.material(glass(1, 1.5))));
    m.draw(m.entity(scene::DiscShape{{0.5, 3, 0.5}, {0, -1, 0}, 0.4}, m.material(diffuse(0, 10)), false));
    m.desc.lights.push_back(pointLight({-1, 4, 1}, 1));
    const PixelBuffer one = renderOk(m.desc, 1), three = renderOk(m.desc, 3);
    CHECK(one.pixels == three.pixels);
}
