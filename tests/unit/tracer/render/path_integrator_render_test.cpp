// The path integrator against scenes whose light has a closed form: each image's mean within
// three standard errors of it, the error estimated from the spread of its pixels (each an
// independent estimate).
#include "path_scene_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = kPathImageSize;

/// The mean of the pixels' channel `channel` over [x0, x1) × [y0, y1), and its standard error.
struct Estimate {
    double mean = 0, standardError = 0;
};

Estimate estimate(const PixelBuffer& image, int channel, int x0 = 0, int y0 = 0, int x1 = kSize, int y1 = kSize) {
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const double v = pixelAt(image, x, y)[channel];
            sum += v, sum2 += v * v, ++n;
        }
    const double mean = sum / n;
    const double variance = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1);
    return {mean, std::sqrt(variance / n)};
}

/// Within three standard errors, and 1/10,000 of the expected value: what the views of a
/// point take in around it (a degree across, at most 3/100,000 less light at their edges
/// under the lamps below) and the rounding of the image's floats. (A pixel's paths spread
/// evenly over their choices, so its standard error can be far below that.)
void checkWithin3Se(const Estimate& e, double expected) {
    INFO("mean " << e.mean << " standard error " << e.standardError << " expected " << expected);
    CHECK(std::abs(e.mean - expected) <= 3 * e.standardError + 1e-4 * expected);
}

/// Draws `part` as a part of a group of 16 (15 black spheres beside it) drawn twice, so an
/// instance of one prototype each time: scaled by `s`, and again 20 under the floor, where
/// its light does not reach. `given`: the drawings' material, for parts without their own.
void drawInSharedEntity(SceneMaker& m, int32_t part, double s, int32_t given = -1) {
    std::vector<int32_t> parts{part};
    for (int k = 0; k < 15; ++k) parts.push_back(m.sphere({k, -5, 0}, 0.1, m.material(diffuse(0))));
    const int32_t group = m.entity(scene::GroupNode{parts});
    m.draw(m.transformed(group, {scale({s, s, s})}, given));
    m.draw(m.transformed(group, {translate({0, -20, 0})}, given));
}

} // namespace

TEST_CASE("path: inside a closed glowing sphere the light is the geometric series of its albedo",
          "[render][path]") {
    // Every bounce meets the sphere again: Le · (1 + ρ + … + ρ^bounces).
    constexpr double kAlbedo = 0.6, kEmission = 0.5;
    for (int bounces : {0, 1, 8}) {
        SceneMaker m;
        m.desc = pathScene(lookAt({0.1, -0.2, 0.05}, {1, 0, 0}, 90), 64, bounces);
        m.draw(m.sphere({0, 0, 0}, 1, m.material(diffuse(kAlbedo, kEmission))));
        const PixelBuffer image = renderOk(m.desc);
        const double expected = kEmission * (1 - std::pow(kAlbedo, bounces + 1)) / (1 - kAlbedo);
        INFO("bounces " << bounces);
        checkWithin3Se(estimate(image, 0), expected);
    }
}

TEST_CASE("path: a white sphere under a uniform white sky is the sky (the white furnace)", "[render][path]") {
    SceneMaker m;
    m.desc = pathScene(lookAt({0, 0, -3}, {0, 0, 0}, 45), 16, 8);
    m.desc.background.color = scene::Color{1, 1, 1, 1};
    m.draw(m.sphere({0, 0, 0}, 1, m.material(diffuse(1))));
    const PixelBuffer image = renderOk(m.desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            INFO("pixel " << x << "," << y);
            CHECK(std::abs(pixelAt(image, x, y).y - 1) < 1e-6);
        }
}

TEST_CASE("path: a Lambertian plane under a uniform sky sends back its albedo times the sky", "[render][path]") {
    constexpr double kAlbedo = 0.35, kSky = 2;
    SceneMaker m;
    m.desc = pathScene(lookAt({0, 5, -1}, {0, 0, 0}, 30), 16, 4);
    m.desc.background.color = scene::Color{kSky, kSky, kSky, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(kAlbedo))));
    const PixelBuffer image = renderOk(m.desc);
    checkWithin3Se(estimate(image, 1), kAlbedo * kSky);
}

TEST_CASE("path: a point under a glowing disc or sphere gets the irradiance of its solid angle",
          "[render][path]") {
    // Seen from straight above, the floor's centre lies under the emitter: its radiance is
    // ρ/π · E, with E = π Le r²/(h² + r²) under a disc of radius r at height h, and
    // E = π Le (r/d)² under a sphere of radius r whose centre is d above it. The light comes
    // both from light sampling and from the bounces' own hits, weighed by MIS, and (scaled
    // by 2) through the emitter's transform.
    constexpr double kAlbedo = 0.8, kEmission = 3, kHeight = 2;
    struct Case {
        const char* name;
        double radius;
        bool sphere;
        double scale;
    };
    for (const Case& c : {Case{"disc", 0.5, false, 1}, Case{"disc scaled", 0.25, false, 2},
                          Case{"sphere", 0.5, true, 1}, Case{"sphere scaled", 0.25, true, 2}}) {
        SceneMaker m = floorSeenFromAbove(256, 1, kAlbedo);
        const int32_t glow = m.material(diffuse(0, kEmission));
        const double r = c.radius * c.scale;
        int32_t emitter = c.sphere ? m.sphere({0, kHeight / c.scale, 0}, c.radius, glow)
                                   : m.entity(scene::DiscShape{{0, kHeight / c.scale, 0}, {0, 1, 0}, c.radius}, glow, false);
        if (c.scale != 1) emitter = m.transformed(emitter, {scale({c.scale, c.scale, c.scale})});
        m.draw(emitter);
        const PixelBuffer image = renderOk(m.desc);
        const double irradiance = c.sphere ? kPi * kEmission * r * r / (kHeight * kHeight)
                                           : kPi * kEmission * r * r / (kHeight * kHeight + r * r);
        INFO(c.name);
        checkWithin3Se(estimate(image, 0), kAlbedo / kPi * irradiance);
    }
}

TEST_CASE("path: a glowing sphere in a CSG tree or in a shared entity's drawings is sampled as a light",
          "[render][path]") {
    // The sphere of the case above (ρ/π · π Le (r/d)² at the floor's centre), now hollowed
    // out by a CSG difference (a hidden cavity), or a part of a group of 16 drawn twice (so an instance of one prototype; the
    // second drawing under the floor), its glow its own or given by the drawing, the drawing
    // scaled by 2. Light sampling's cone leaves each pixel's paths almost no spread; found by
    // the paths' bounces alone, one path in sixteen meets the sphere and pixels spread by
    // a tenth or more.
    constexpr double kAlbedo = 0.8, kEmission = 3, kHeight = 2, kRadius = 0.5;
    enum class Holder { Difference, Instance, InstanceGivesGlow, InstanceScaled };
    for (Holder holder : {Holder::Difference, Holder::Instance, Holder::InstanceGivesGlow, Holder::InstanceScaled}) {
        SceneMaker m = floorSeenFromAbove(64, 1, kAlbedo);
        const int32_t glow = m.material(diffuse(0, kEmission));
        const double s = holder == Holder::InstanceScaled ? 2 : 1;
        const int32_t sphere = m.sphere({0, kHeight / s, 0}, kRadius / s, holder == Holder::InstanceGivesGlow ? -1 : glow);
        if (holder == Holder::Difference)
            m.draw(m.csg(scene::CsgOp::Difference, sphere, m.sphere({0, kHeight, 0}, kRadius / 2, m.material(diffuse(0)))));
        else
            drawInSharedEntity(m, sphere, s, holder == Holder::InstanceGivesGlow ? glow : -1);
        std::string error;
        const auto built = buildRenderScene(m.desc, error);
        REQUIRE(built);
        CHECK(built->instances.size() == (holder == Holder::Difference ? 0u : 2u));
        const PixelBuffer image = renderOk(m.desc);
        const Estimate e = estimate(image, 0);
        const double expected = kAlbedo / kPi * kPi * kEmission * kRadius * kRadius / (kHeight * kHeight);
        INFO("holder " << static_cast<int>(holder));
        checkWithin3Se(e, expected);
        const double pixelSpread = e.standardError * kSize / e.mean;
        INFO("pixels spread by " << pixelSpread);
        CHECK(pixelSpread < 0.01);
    }
}

TEST_CASE("path: a glowing mesh is sampled as a light, drawn directly or in a shared entity's drawings",
          "[render][path]") {
    // A square of two triangles, of half-side a, glowing with Le at height h above the floor's
    // centre: E = π Le · 4F, F the view factor from a point to an a × a rectangle above its
    // corner, 1/(2π) · 2 · X/√(1+X²) · atan(X/√(1+X²)) with X = a/h. The floor sends back
    // ρ/π · E. The mesh is drawn once, or inside a group of 16 drawn twice (scaled by 2, the
    // second under the floor); each drawing's faces come from one face table.
    constexpr double kAlbedo = 0.8, kEmission = 3, kHeight = 2, kHalf = 0.5;
    for (const bool instanced : {false, true}) {
        SceneMaker m = floorSeenFromAbove(64, 1, kAlbedo);
        const double s = instanced ? 2 : 1, a = kHalf / s, y = kHeight / s;
        auto square = std::make_shared<scene::MeshData>();
        square->positions = {{-a, y, -a}, {a, y, -a}, {a, y, a}, {-a, y, a}};
        square->triangles = {{{0, 1, 2}, {-1, -1, -1}, {-1, -1, -1}}, {{0, 2, 3}, {-1, -1, -1}, {-1, -1, -1}}};
        m.desc.writtenMeshes.push_back(square);
        scene::MeshShape shape;
        shape.written = 0;
        const int32_t mesh = m.entity(shape, m.material(diffuse(0, kEmission)), false);
        if (instanced)
            drawInSharedEntity(m, mesh, s);
        else
            m.draw(mesh);
        const PixelBuffer image = renderOk(m.desc);
        const double x = kHalf / kHeight, root = std::sqrt(1 + x * x);
        const double viewFactor = 4 * (2 * x / root * std::atan(x / root)) / (2 * kPi);
        const Estimate e = estimate(image, 0);
        INFO((instanced ? "instanced" : "drawn directly"));
        checkWithin3Se(e, kAlbedo * kEmission * viewFactor);
        CHECK(e.standardError * kSize / e.mean < 0.05);
    }
}

TEST_CASE("path: light sampling does not light from what a CSG tree carved off an emitter", "[render][path]") {
    // A glowing sphere less a box that takes its lower half: seen from the floor below, only
    // the black cut face, with the glowing dome behind it. Points drawn on the carved half are
    // in plain view of the floor (the box is no surface outside the sphere), so they must be
    // seen not to be there: the floor stays black. With them counted, it would get ρ/π · E.
    SceneMaker m = floorSeenFromAbove(16, 1, 0.8);
    const int32_t glowing = m.sphere({0, 2, 0}, 0.5, m.material(diffuse(0, 3)));
    m.draw(m.csg(scene::CsgOp::Difference, glowing, m.box({-1, 1.2, -1}, {1, 2, 1}, m.material(diffuse(0)))));
    const PixelBuffer image = renderOk(m.desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            INFO("pixel " << x << "," << y);
            CHECK(maxDifference(pixelAt(image, x, y), DVec3(0.0)) == 0);
        }
}

TEST_CASE("path: a point light lights a Lambertian surface as under the Whitted integrator", "[render][path]") {
    // A light of colour L gives a white diffuse surface L·cos θ under both (docs/rendering.md).
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 1, 0}, {0, 0, 0}, 1);
    camera.up = {0, 0, 1};
    m.desc = pathScene(camera, 4, 3);
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(0.5))));
    scene::LightDesc light;
    light.kind = scene::LightKind::Point;
    light.origin = {3, 4, 0};
    light.color = scene::Color{2, 2, 2, 1};
    m.desc.lights.push_back(light);
    const PixelBuffer path = renderOk(m.desc);
    m.desc.settings.integrator = scene::Integrator::Whitted;
    const PixelBuffer whitted = renderOk(m.desc);
    const double expected = 0.5 * 2 * 4 / 5; // ρ · L · cos θ
    CHECK(std::abs(pixelAt(whitted, kSize / 2, kSize / 2).x - expected) < 1e-3);
    CHECK(std::abs(pixelAt(path, kSize / 2, kSize / 2).x - expected) < 1e-3);
}

TEST_CASE("path: the same scene and seed give the same bits on any number of threads", "[render][path]") {
    SceneMaker m;
    m.desc = pathScene(lookAt({0, 1, -4}, {0, 0.5, 0}, 50), 8, 6);
    m.desc.background.color = scene::Color{0.3, 0.4, 0.9, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(0.7))));
    m.draw(m.sphere({0, 0.6, 0}, 0.6, m.material(diffuse(0.2, 4))));
    const PixelBuffer one = renderOk(m.desc, 1);
    const PixelBuffer two = renderOk(m.desc, 2);
    CHECK(one.pixels == two.pixels);
    m.desc.settings.seed = 7;
    CHECK(renderOk(m.desc, 2).pixels != one.pixels);
}

namespace {

/// Renders and returns the outcome (its stats) beside the image.
PixelBuffer renderCounting(const scene::SceneDesc& desc, RenderOutcome& outcome) {
    RenderJob job;
    PixelBuffer image(desc.settings.width, desc.settings.height);
    job.onTileDone = [&](const TileResult& tile) { image.place(tile); };
    outcome = render(desc, job);
    REQUIRE(outcome.ok);
    return image;
}

} // namespace

TEST_CASE("path: with a target error, a pixel takes the paths it needs", "[render][path]") {
    constexpr uint64_t kPixels = kSize * kSize;
    SECTION("a flat sky is exact after the first batch: every pixel stops there") {
        SceneMaker m;
        m.desc = pathScene(lookAt({0, 0, -3}, {0, 0, 0}, 45), 1024, 8);
        m.desc.settings.targetError = 0.01;
        m.desc.background.color = scene::Color{1, 1, 1, 1};
        m.draw(m.sphere({0, 0, 0}, 1, m.material(diffuse(1))));
        RenderOutcome outcome;
        renderCounting(m.desc, outcome);
        CHECK(outcome.stats.cameraRays == kPixels * scene::SettingsDesc::kMinAdaptiveSamples);
        CHECK(outcome.stats.pathPixels == kPixels);
        CHECK(outcome.stats.fewestPaths == scene::SettingsDesc::kMinAdaptiveSamples);
        CHECK(outcome.stats.mostPaths == scene::SettingsDesc::kMinAdaptiveSamples);
        CHECK(outcome.stats.imageRelativeError() == 0);
    }
    SECTION("under a glowing disc, the pixels stop between the first batch and samples, at the light") {
        constexpr double kAlbedo = 0.8, kEmission = 3, kHeight = 2, kRadius = 0.5;
        SceneMaker m;
        scene::CameraDesc camera = lookAt({0, 1, 0}, {0, 0, 0}, 1);
        camera.up = {0, 0, 1};
        m.desc = pathScene(camera, 4096, 1);
        m.desc.settings.targetError = 0.002;
        m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(kAlbedo))));
        m.draw(m.entity(scene::DiscShape{{0, kHeight, 0}, {0, 1, 0}, kRadius}, m.material(diffuse(0, kEmission)), false));
        RenderOutcome outcome;
        const PixelBuffer image = renderCounting(m.desc, outcome);
        CHECK(outcome.stats.cameraRays > kPixels * scene::SettingsDesc::kMinAdaptiveSamples);
        CHECK(outcome.stats.cameraRays < kPixels * 4096);
        // Every pixel stopped at the target, so the image's error (their root mean square) is
        // within it too, and the counts it reports bound the mean.
        CHECK(outcome.stats.imageRelativeError() <= 0.002);
        CHECK(outcome.stats.imageRelativeError() > 0.001);
        CHECK(outcome.stats.fewestPaths * kPixels <= outcome.stats.cameraRays);
        CHECK(outcome.stats.mostPaths * kPixels >= outcome.stats.cameraRays);
        const double irradiance = kPi * kEmission * kRadius * kRadius / (kHeight * kHeight + kRadius * kRadius);
        checkWithin3Se(estimate(image, 0), kAlbedo / kPi * irradiance);
        // Each pixel's own error is within the target: no pixel strays by much more.
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                CHECK(std::abs(pixelAt(image, x, y).x / (kAlbedo / kPi * irradiance) - 1) < 5 * 0.002);
    }
}

TEST_CASE("path: an area light lights a Lambertian surface as the Whitted integrator's samples do",
          "[render][path]") {
    // Light sampling and the bounces that meet the light share the estimate by MIS: counted
    // by both, the floor would be too bright by up to twice.
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 1, 0}, {0, 0, 0}, 1);
    camera.up = {0, 0, 1};
    m.desc = pathScene(camera, 256, 1);
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(0.5))));
    m.desc.lights.push_back(areaLight(6, 2, 1));
    const PixelBuffer path = renderOk(m.desc);
    m.desc.settings.integrator = scene::Integrator::Whitted;
    m.desc.settings.shadowSamples = 4096;
    const double whitted = pixelAt(renderOk(m.desc), kSize / 2, kSize / 2).x;
    INFO("Whitted " << whitted);
    checkWithin3Se(estimate(path, 0), whitted);
}

TEST_CASE("path: a mirror shows an area light the camera does not see", "[render][path]") {
    // The camera looks down at a mirror floor from the light's height; the reflected rays
    // meet the light, whose radiance is what gives light sampling's estimate: π L d² / (A cos θ).
    SceneMaker m;
    m.desc = pathScene(lookAt({0, 2, -1}, {0, 0, 0}, 0.5), 4, 2);
    ShadingMaterial mirror;
    mirror.color = scene::Color{1, 1, 1, 1};
    mirror.diffuse = 0;
    mirror.reflectivity = 1;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(mirror)));
    m.desc.lights.push_back(areaLight(4, 2, 1));
    const double seen = pixelAt(renderOk(m.desc), kSize / 2, kSize / 2).x;
    // The middle ray meets the floor at the origin and the light at (0, 2, 1): d = √5, cos θ = 2/√5.
    const double expected = kPi * 5 / (16 * 2 / std::sqrt(5.0));
    CHECK(std::abs(seen / expected - 1) < 0.01);
    // Looking up at it, the camera sees only the black background.
    m.desc.camera = lookAt({0, 0.5, 0}, {0, 3, 0.01}, 10);
    for (float v : renderOk(m.desc).pixels) CHECK(v == 0);
}

TEST_CASE("path: an area light lights a floor through a clear pane by the share the pane lets through",
          "[render][path]") {
    // Light sampling's shadow rays stop at the glass, so the floor gets only the paths that
    // cross the pane and meet the light. Each point of the light lights as a point light
    // does, which keeps its strength through glass that bends nothing: the floor gets the
    // pane's transparency times its light without the pane. (Reckoned from the pane, the
    // distance to the light would be half the path's, and the light a quarter of that.)
    constexpr double kTransparency = 0.6;
    SceneMaker m = floorSeenFromAbove(256, 3, 0.5);
    m.desc.camera = lookAt({0, 0.5, 0}, {0, 0, 0}, 1); // below the pane
    m.desc.camera.up = {0, 0, 1};
    m.desc.lights.push_back(areaLight(6, 2, 1));
    m.desc.settings.integrator = scene::Integrator::Whitted;
    m.desc.settings.shadowSamples = 4096;
    const double bare = pixelAt(renderOk(m.desc), kSize / 2, kSize / 2).x;
    m.desc.settings.integrator = scene::Integrator::Path;
    ShadingMaterial pane;
    pane.color = scene::Color{1, 1, 1, 1};
    pane.diffuse = 0;
    pane.transparency = kTransparency;
    pane.ior = 1.5;
    m.draw(m.entity(scene::DiscShape{{0, 1, 0}, {0, 1, 0}, 20}, m.material(pane), false));
    INFO("without the pane " << bare);
    checkWithin3Se(estimate(renderOk(m.desc), 0), kTransparency * bare);
}
