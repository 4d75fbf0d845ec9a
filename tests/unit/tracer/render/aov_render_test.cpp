// The AOVs of a path-traced render (RenderJob::aovs): the albedo and normal of what a pixel's
// paths first meet, and the variance of its mean, beside a colour image they leave as it was.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 16;

/// A render's colour and each AOV as images of three floats a pixel.
struct AovImages {
    PixelBuffer color{kSize, kSize}, variance{kSize, kSize}, albedo{kSize, kSize}, normal{kSize, kSize};
};

AovImages renderAovs(const scene::SceneDesc& desc, bool progressive = false) {
    AovImages out;
    RenderJob job;
    job.aovs.add(Aov::Variance);
    job.aovs.add(Aov::Albedo);
    job.aovs.add(Aov::Normal);
    if (progressive) job.progressive = ProgressiveRender{};
    REQUIRE(job.channels() == 12);
    job.onTileDone = [&](const TileResult& tile) {
        const size_t n = static_cast<size_t>(tile.tile.width()) * tile.tile.height();
        PixelBuffer* images[4] = {&out.color, &out.variance, &out.albedo, &out.normal};
        for (size_t k = 0; k < 4; ++k) {
            std::vector<float> part(n * 3);
            for (size_t i = 0; i < n; ++i)
                for (size_t c = 0; c < 3; ++c) part[i * 3 + c] = tile.pixels[i * 12 + k * 3 + c];
            images[k]->place(TileResult{tile.tile, tile.index, 3, part});
        }
    };
    const RenderOutcome outcome = render(desc, job);
    INFO(outcome.error);
    REQUIRE(outcome.ok);
    return out;
}

ShadingMaterial diffuse(DVec3 albedo) {
    ShadingMaterial m;
    m.color = scene::Color{albedo.x, albedo.y, albedo.z, 1};
    m.diffuse = 1;
    return m;
}

/// Looking down at a grey plane under a blue sky, a red ball and a mirror ball on it.
scene::SceneDesc ballsOnPlane(int samples) {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 3, -3}, {0, 0, 0}, 60));
    m.desc.settings.integrator = scene::Integrator::Path;
    m.desc.settings.samples = samples;
    m.desc.background.color = scene::Color{0.3, 0.4, 0.9, 1};
    ShadingMaterial mirror;
    mirror.color = scene::Color{1, 1, 1, 1};
    mirror.diffuse = 0;
    mirror.reflectivity = 1;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse({0.5, 0.5, 0.5}))));
    m.draw(m.sphere({-0.8, 0.5, 0}, 0.5, m.material(diffuse({0.9, 0.1, 0.1}))));
    m.draw(m.sphere({0.8, 0.5, 0}, 0.5, m.material(mirror)));
    return m.desc;
}

} // namespace

TEST_CASE("aov: the colour image is the same bits with AOVs or without", "[render][path]") {
    const scene::SceneDesc desc = ballsOnPlane(8);
    const AovImages aovs = renderAovs(desc);
    CHECK(aovs.color.pixels == renderOk(desc).pixels);
    CHECK(renderAovs(desc, true).albedo.pixels == aovs.albedo.pixels);
    CHECK(renderAovs(desc, true).variance.pixels == aovs.variance.pixels);
}

TEST_CASE("aov: albedo and normal are those of the first surface a path can light, through mirrors",
          "[render][path]") {
    const AovImages aovs = renderAovs(ballsOnPlane(8));
    int plane = 0, redSeen = 0, redMirrored = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const DVec3 albedo = pixelAt(aovs.albedo, x, y), normal = pixelAt(aovs.normal, x, y);
            INFO("pixel " << x << ", " << y << " albedo " << albedo.x << " " << albedo.y << " " << albedo.z);
            // Every albedo is a mean of the plane's, the red ball's and the sky's nothing:
            // never the mirror's own white.
            CHECK(albedo.y <= 0.5 + 1e-6);
            if (glm::distance(albedo, DVec3(0.5)) < 1e-6 && glm::distance(normal, DVec3(0, 1, 0)) < 1e-6) ++plane;
            if (glm::distance(albedo, DVec3(0.9, 0.1, 0.1)) < 1e-6) {
                CHECK(glm::length(normal) > 0.8); // the mean of the normals over the pixel
                CHECK(glm::length(normal) <= 1 + 1e-6);
                // The red ball's side towards the camera (-z), or, in the mirror ball to its
                // right, its side towards the mirror (+x).
                if (normal.z < -0.3) ++redSeen;
                if (normal.x > 0.5 && normal.z > -0.3) ++redMirrored;
            }
        }
    CHECK(plane > kSize * kSize / 4);
    CHECK(redSeen > 0);
    CHECK(redMirrored > 0);
}

TEST_CASE("aov: the variance is that of each pixel's mean, as independent paths would make it",
          "[render][path]") {
    // A small patch of a plane under a glowing disc: every pixel is an estimate of the same
    // light, so the spread of the pixels is the spread of one pixel's mean.
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 1, 0}, {0, 0, 0}, 1);
    camera.up = {0, 0, 1};
    m.desc = blankScene(kSize, kSize, camera);
    m.desc.settings.integrator = scene::Integrator::Path;
    m.desc.settings.samples = 16;
    m.desc.settings.bounces = 1;
    ShadingMaterial lamp = diffuse({0, 0, 0});
    lamp.emission = scene::Color{3, 3, 3, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse({0.8, 0.8, 0.8}))));
    m.draw(m.entity(scene::DiscShape{{0, 2, 0}, {0, 1, 0}, 0.5}, m.material(lamp), false));
    // The variance of one path, from the spread of one-path pixels (each pixel's paths are
    // independent of the others').
    m.desc.settings.samples = 1;
    const AovImages single = renderAovs(m.desc);
    m.desc.settings.samples = 16;
    const AovImages aovs = renderAovs(m.desc);
    double sum = 0, sumSquares = 0, meanVariance = 0;
    int n = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = pixelAt(single.color, x, y).x;
            sum += v, sumSquares += v * v, meanVariance += pixelAt(aovs.variance, x, y).x, ++n;
        }
    const double pathVariance = (sumSquares / n - sum / n * sum / n) * n / (n - 1);
    meanVariance /= n;
    INFO("one path's variance " << pathVariance << ", the 16-path pixels' variance " << meanVariance);
    // s²/16, estimated from 256 pixels, is within a fifth or so of the variance of one path
    // over 16.
    CHECK(meanVariance > 0.7 * pathVariance / 16);
    CHECK(meanVariance < 1.4 * pathVariance / 16);
    // A pixel's paths spread evenly over their choices (SampleRng::sequence), so its mean
    // varies less between pixels than 16 independent paths' would: s²/n bounds it.
    double sum16 = 0, squares16 = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = pixelAt(aovs.color, x, y).x;
            sum16 += v, squares16 += v * v;
        }
    CHECK((squares16 / n - sum16 / n * sum16 / n) * n / (n - 1) < meanVariance);
}

TEST_CASE("aov: the Whitted integrator has none", "[render]") {
    scene::SceneDesc desc = ballsOnPlane(8);
    desc.settings.integrator = scene::Integrator::Whitted;
    RenderJob job;
    job.aovs.add(Aov::Albedo);
    const RenderOutcome outcome = render(desc, job);
    CHECK(!outcome.ok);
    CHECK(outcome.error == "AOVs are written by the path integrator only");
}
