// Analytic render tests of media: a box of glass that does not bend light (ior 1), filled
// with a medium, seen straight through by an orthographic camera, so every ray crosses the
// same width of it at a height known from its pixel row.
//
// Absorption alone is Beer's law; emission adds E/σ·(1 − e^(−σw)); single scattering of a
// light straight above, through the medium's own height h − y, adds
// σs·π·p·L·e^(−σ(h−y))·(1 − e^(−σw))/σ (with the convention that a light of colour L gives a
// white Lambertian surface L·cos θ, its irradiance is π·L). The path integrator, its light
// bouncing once, gives the same; with every bounce, a medium that gives off what it absorbs
// (E = σa·B) in a furnace of radiance B is not seen at all, however it scatters.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "tracer/medium.hpp"
#include "tracer/sampling.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 16;
constexpr double kWidth = 2;  ///< of the medium along the view
constexpr double kHeight = 2; ///< of the box: y from 0 to 2
const DVec3 kBehind{0.8, 0.7, 0.6};

/// The box filled with `medium`, lit by `lights`, seen along +z through its middle.
scene::SceneDesc mediumBox(const scene::MediumDesc& medium, std::vector<scene::LightDesc> lights = {}) {
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 1, -5}, {0, 1, 0}, 60);
    camera.projection = scene::Projection::Orthographic;
    camera.width = 4;
    m.desc = blankScene(kSize, kSize, camera);
    m.desc.background.color = {kBehind.x, kBehind.y, kBehind.z, 1};
    m.desc.media.push_back(medium);
    ShadingMaterial glass;
    glass.color = scene::Color{1, 1, 1, 1};
    glass.diffuse = 0;
    glass.transparency = 1;
    glass.ior = 1;
    glass.medium = 0;
    m.draw(m.box({-1, 0, 0}, {1, kHeight, kWidth}, m.material(glass)));
    m.desc.lights = std::move(lights);
    m.desc.settings.recursionDepth = 4;
    return m.desc;
}

/// The height of pixel row `y`'s rays, and whether they cross the box well inside it.
double rowHeight(int y) { return 1 + (1 - 2 * (y + 0.5) / kSize) * 2; }
bool inside(int x, int y) {
    const double across = (2 * (x + 0.5) / kSize - 1) * 2, height = rowHeight(y);
    return std::abs(across) < 0.9 && height > 0.1 && height < kHeight - 0.1;
}
bool outside(int x, int y) {
    const double across = (2 * (x + 0.5) / kSize - 1) * 2, height = rowHeight(y);
    return std::abs(across) > 1.1 || height < -0.1 || height > kHeight + 0.1;
}

/// Checks the pixels inside the box against want(height), those beside it against the
/// background.
template <typename Want>
void checkBox(const scene::SceneDesc& desc, Want&& want, double tolerance = 1e-6) {
    const DVec3 behind = rgbOf(desc.background.color);
    const PixelBuffer image = renderOk(desc);
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            INFO("pixel " << x << "," << y << " height " << rowHeight(y));
            if (inside(x, y)) {
                CHECK(maxDifference(pixelAt(image, x, y), want(rowHeight(y))) < tolerance);
                ++checked;
            } else if (outside(x, y)) {
                CHECK(maxDifference(pixelAt(image, x, y), behind) < 1e-6);
            }
        }
    REQUIRE(checked > 50);
}

DVec3 expOf(const DVec3& v) { return {std::exp(v.x), std::exp(v.y), std::exp(v.z)}; }

/// The scene under the path integrator, light bouncing once (single scattering).
scene::SceneDesc pathTraced(scene::SceneDesc desc, int samples) {
    desc.settings.integrator = scene::Integrator::Path;
    desc.settings.samples = samples;
    desc.settings.bounces = 1;
    return desc;
}

/// An absorbing medium whose density is a gradient along y: the density at height y (below
/// 1) is y, the same along each ray.
scene::MediumDesc gradientMedium() {
    scene::MediumDesc medium;
    medium.absorption = {0.8, 0.8, 0.8, 1};
    scene::TextureDesc gradient = scene::defaultTexture(scene::TextureKind::Gradient);
    gradient.axis = {0, 1, 0};
    medium.densityPattern.push_back(gradient);
    return medium;
}

/// Checks the middle column's rows below height 1 against Beer's law at their height.
void checkGradientDensity(const scene::SceneDesc& desc, double tolerance) {
    const PixelBuffer image = renderOk(desc);
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        const double h = rowHeight(y);
        if (h < 0.1 || h > 0.9) continue;
        const DVec3 want = kBehind * std::exp(-0.8 * h * kWidth);
        INFO("height " << h);
        CHECK(maxDifference(pixelAt(image, kSize / 2, y), want) < tolerance);
        ++checked;
    }
    CHECK(checked >= 3);
}

} // namespace

TEST_CASE("an absorbing medium lets exp(-a w) of what is behind through (Beer)", "[render][analytic][medium]") {
    scene::MediumDesc medium;
    medium.absorption = {0.3, 0.6, 0.9, 1};
    const DVec3 a = rgbOf(medium.absorption);
    checkBox(mediumBox(medium), [&](double) { return kBehind * expOf(-a * kWidth); });
    // Half as dense, half the loss.
    medium.density = 0.5;
    checkBox(mediumBox(medium), [&](double) { return kBehind * expOf(-a * (kWidth / 2)); });
}

TEST_CASE("a glowing medium adds E/a (1 - exp(-a w))", "[render][analytic][medium]") {
    scene::MediumDesc medium;
    medium.absorption = {0.5, 0.5, 0.5, 1};
    medium.emission = {0.4, 0.2, 0.1, 1};
    const DVec3 a = rgbOf(medium.absorption), e = rgbOf(medium.emission);
    const DVec3 loss = expOf(-a * kWidth);
    checkBox(mediumBox(medium), [&](double) { return e / a * (DVec3(1.0) - loss) + kBehind * loss; });
}

TEST_CASE("the path integrator's paths through absorbing and glowing media are Beer's law exactly",
          "[render][analytic][medium]") {
    scene::MediumDesc medium;
    medium.absorption = {0.3, 0.6, 0.9, 1};
    medium.emission = {0.4, 0.2, 0.1, 1};
    const DVec3 a = rgbOf(medium.absorption), e = rgbOf(medium.emission);
    const DVec3 loss = expOf(-a * kWidth);
    checkBox(pathTraced(mediumBox(medium), 4), [&](double) { return e / a * (DVec3(1.0) - loss) + kBehind * loss; });
}

TEST_CASE("a camera inside a filled solid sees through what fills it from its first step",
          "[render][analytic][medium]") {
    // The orthographic camera stands inside a box of glowing, absorbing medium, whose far face
    // is kWidth ahead of every ray: each crosses kWidth of it, as through the box above.
    scene::MediumDesc medium;
    medium.absorption = {0.3, 0.6, 0.9, 1};
    medium.emission = {0.4, 0.2, 0.1, 1};
    scene::SceneDesc desc = mediumBox(medium);
    desc.camera = lookAt({0, 1, 0}, {0, 1, 1}, 60);
    desc.camera.projection = scene::Projection::Orthographic;
    desc.camera.width = 1.5;
    scene::EntityDesc& box = desc.entities.back();
    box.shape = scene::BoxShape{{-3, -2, -3}, {3, 4, kWidth}};
    const DVec3 a = rgbOf(medium.absorption), e = rgbOf(medium.emission);
    const DVec3 loss = expOf(-a * kWidth);
    const DVec3 want = e / a * (DVec3(1.0) - loss) + kBehind * loss;
    for (const bool path : {false, true}) {
        INFO((path ? "path" : "whitted"));
        const PixelBuffer image = renderOk(path ? pathTraced(desc, 4) : desc);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) CHECK(maxDifference(pixelAt(image, x, y), want) < 1e-6);
    }
}

TEST_CASE("the path integrator tracks a medium whose density is a pattern", "[render][analytic][medium]") {
    // Each path passes or is absorbed, so the pixel is a mean.
    checkGradientDensity(pathTraced(mediumBox(gradientMedium()), 4096), 0.03);
}

TEST_CASE("a medium's density pattern scales it point by point", "[render][analytic][medium]") {
    checkGradientDensity(mediumBox(gradientMedium()), 1e-6);
}

TEST_CASE("single scattering of a light above a homogeneous medium matches its closed form",
          "[render][analytic][medium]") {
    scene::MediumDesc medium;
    medium.scattering = {0.5, 0.25, 0.1, 1};
    medium.absorption = {0.1, 0.1, 0.1, 1};
    medium.samples = 8;
    const DVec3 light{1.5, 1.2, 1.0};
    const DVec3 sigmaS = rgbOf(medium.scattering), sigmaT = sigmaS + rgbOf(medium.absorption);
    const DVec3 loss = expOf(-sigmaT * kWidth);
    checkBox(mediumBox(medium, {parallelLight({0, 10, 0}, {0, 0, 0}, {light.x, light.y, light.z, 1})}),
             [&](double h) {
                 const DVec3 reaching = light * expOf(-sigmaT * (kHeight - h));
                 const DVec3 scattered = sigmaS * (kTestPi / (4 * kTestPi)) * reaching * (DVec3(1.0) - loss) / sigmaT;
                 return scattered + kBehind * loss;
             },
             1e-5);
}

TEST_CASE("the path integrator's single scattering matches the same closed form", "[render][analytic][medium]") {
    scene::MediumDesc medium;
    medium.scattering = {0.5, 0.25, 0.1, 1};
    medium.absorption = {0.1, 0.1, 0.1, 1};
    const DVec3 light{1.5, 1.2, 1.0};
    const DVec3 sigmaS = rgbOf(medium.scattering), sigmaT = sigmaS + rgbOf(medium.absorption);
    const DVec3 loss = expOf(-sigmaT * kWidth);
    // Each path scatters at its own point of its own pixel: the mean over the pixel's heights.
    // Against a black background, as light from the background would scatter too.
    const double pixel = 4.0 / kSize;
    scene::SceneDesc desc = mediumBox(medium, {parallelLight({0, 10, 0}, {0, 0, 0}, {light.x, light.y, light.z, 1})});
    desc.background.color = {0, 0, 0, 1};
    checkBox(pathTraced(desc, 4096),
             [&](double h) {
                 const DVec3 reaching = light * expOf(-sigmaT * (kHeight - h)) * (DVec3(2.0) / (sigmaT * pixel)) *
                                        DVec3(std::sinh(sigmaT.x * pixel / 2), std::sinh(sigmaT.y * pixel / 2),
                                              std::sinh(sigmaT.z * pixel / 2));
                 return sigmaS * (kTestPi / (4 * kTestPi)) * reaching * (DVec3(1.0) - loss) / sigmaT;
             },
             0.01);
}

TEST_CASE("in a furnace, a medium that gives off what it absorbs is not seen, however it scatters",
          "[render][analytic][medium]") {
    // The radiance B everywhere solves the transfer equation: along any ray, σa·B is absorbed
    // and E = σa·B given off, and what scatters in equals what scatters out.
    const DVec3 furnace{0.7, 0.8, 0.9}, absorption{0.4, 0.5, 0.6};
    for (bool patterned : {false, true}) {
        scene::MediumDesc medium;
        medium.scattering = {0.8, 0.5, 0.3, 1};
        medium.absorption = {absorption.x, absorption.y, absorption.z, 1};
        const DVec3 e = absorption * furnace;
        medium.emission = {e.x, e.y, e.z, 1};
        medium.phase = scene::PhaseFunction::HenyeyGreenstein;
        medium.g = 0.5;
        medium.density = 3;
        if (patterned) medium.densityPattern.push_back(scene::defaultTexture(scene::TextureKind::Granite));
        scene::SceneDesc desc = mediumBox(medium);
        desc.background.color = {furnace.x, furnace.y, furnace.z, 1};
        desc = pathTraced(desc, 1024);
        desc.settings.bounces = 1000;
        const PixelBuffer image = renderOk(desc);
        DVec3 sum(0.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                INFO("pixel " << x << "," << y << (patterned ? " patterned" : ""));
                CHECK(maxDifference(pixelAt(image, x, y), furnace) < 0.05);
                sum += pixelAt(image, x, y);
            }
        INFO((patterned ? "patterned" : "homogeneous"));
        CHECK(maxDifference(sum / double(kSize * kSize), furnace) < 0.005);
    }
}

TEST_CASE("the phase functions' draws follow their densities", "[medium]") {
    // E[cos θ] = g for Henyey–Greenstein; E[cos² θ] = 1/3 for the isotropic one and 2/5 for
    // Rayleigh's (3/8)(1 + c²).
    const Vec3 d = glm::normalize(Vec3(0.3, -0.5, 0.8));
    auto moments = [&](scene::PhaseFunction phase, double g) {
        scene::MediumDesc desc;
        desc.phase = phase;
        desc.g = g;
        const Medium medium(desc);
        constexpr int kDraws = 400000;
        SampleRng rng(7, 0, 0);
        double sum = 0, squares = 0, longest = 0;
        for (int i = 0; i < kDraws; ++i) {
            const Vec3 wi = medium.samplePhase(d, rng.uniform2());
            longest = std::max(longest, std::abs(glm::length(wi) - 1));
            const double c = glm::dot(wi, d);
            sum += c, squares += c * c;
        }
        CHECK(longest < 1e-12); // unit directions
        return std::pair{sum / kDraws, squares / kDraws};
    };
    for (double g : {-0.6, 0.0, 0.3, 0.9}) {
        INFO("g " << g);
        CHECK(moments(scene::PhaseFunction::HenyeyGreenstein, g).first == Approx(g).margin(0.005));
    }
    CHECK(moments(scene::PhaseFunction::Isotropic, 0).second == Approx(1.0 / 3).margin(0.005));
    CHECK(moments(scene::PhaseFunction::Rayleigh, 0).second == Approx(0.4).margin(0.005));
    CHECK(moments(scene::PhaseFunction::Rayleigh, 0).first == Approx(0).margin(0.005));
}

TEST_CASE("the phase functions are densities over the sphere, forward or back as g says", "[medium]") {
    for (scene::PhaseFunction phase :
         {scene::PhaseFunction::Isotropic, scene::PhaseFunction::Rayleigh, scene::PhaseFunction::HenyeyGreenstein}) {
        for (double g : {-0.6, 0.0, 0.8}) {
            scene::MediumDesc desc;
            desc.phase = phase;
            desc.g = g;
            const Medium medium(desc);
            // ∫ p dω = 2π ∫₋₁¹ p(c) dc, by the midpoint rule.
            constexpr int kSteps = 200000;
            double sum = 0;
            for (int i = 0; i < kSteps; ++i) sum += medium.phase(-1 + (i + 0.5) * 2.0 / kSteps);
            INFO("phase " << int(phase) << " g " << g);
            CHECK(2 * kTestPi * sum * 2.0 / kSteps == Approx(1).epsilon(1e-6));
            if (phase == scene::PhaseFunction::HenyeyGreenstein && g != 0)
                CHECK((medium.phase(1) > medium.phase(-1)) == (g > 0));
        }
    }
}
