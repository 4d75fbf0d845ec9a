// Progressive path-traced renders (RenderJob::progressive): passes that end in the image a
// render in one pass makes, a deadline that stops them with the image so far, and the
// images shown after each pass.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 24;

/// A diffuse sphere on a plane under a sky and a glowing ball: light that bounces, in pixels
/// that converge at different rates.
scene::SceneDesc litScene(int samples, double targetError) {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 1, -4}, {0, 0.5, 0}, 50));
    m.desc.settings.integrator = scene::Integrator::Path;
    m.desc.settings.samples = samples;
    m.desc.settings.targetError = targetError;
    m.desc.background.color = scene::Color{0.3, 0.4, 0.9, 1};
    ShadingMaterial grey, lamp;
    grey.color = scene::Color{0.7, 0.7, 0.7, 1};
    lamp.color = scene::Color{0.2, 0.2, 0.2, 1};
    lamp.emission = scene::Color{4, 3, 2, 1};
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(grey)));
    m.draw(m.sphere({0.8, 0.3, 0}, 0.3, m.material(lamp)));
    m.draw(m.sphere({-0.4, 0.6, 0.3}, 0.6, m.material(grey)));
    return m.desc;
}

struct Rendered {
    PixelBuffer image;
    RenderOutcome outcome;
    std::vector<PassImage> passes; ///< what onPass saw (without its image)
    std::vector<std::vector<float>> passPixels;
};

Rendered renderJob(const scene::SceneDesc& desc, std::optional<ProgressiveRender> progressive, int threads = 2) {
    Rendered r{PixelBuffer(desc.settings.width, desc.settings.height), {}, {}, {}};
    RenderJob job;
    job.threads = threads;
    job.onTileDone = [&](const TileResult& tile) { r.image.place(tile); };
    if (progressive) {
        progressive->onPass = [&](const PassImage& pass) {
            r.passes.push_back(pass);
            r.passPixels.push_back(pass.image->pixels);
        };
    }
    job.progressive = std::move(progressive);
    r.outcome = render(desc, job);
    return r;
}

} // namespace

TEST_CASE("progressive: the passes end in the same bits as a render in one pass", "[render][path]") {
    for (double targetError : {0.0, 0.05}) {
        INFO("target error " << targetError);
        const scene::SceneDesc desc = litScene(64, targetError);
        const Rendered once = renderJob(desc, std::nullopt);
        const Rendered passes = renderJob(desc, ProgressiveRender{});
        REQUIRE(once.outcome.ok);
        REQUIRE(passes.outcome.ok);
        CHECK(passes.image.pixels == once.image.pixels);
        CHECK(passes.outcome.stats.cameraRays == once.outcome.stats.cameraRays);
        CHECK(passes.outcome.stats.squaredErrors == once.outcome.stats.squaredErrors);
        CHECK(passes.outcome.tilesDone == passes.outcome.tileCount);
        // 1, 2, 4, 8, 16, 32, 48, 64 paths: eight passes, or fewer when every pixel settles.
        REQUIRE(!passes.passes.empty());
        CHECK(passes.passes.size() <= 8);
        CHECK(passes.passes.front().meanPaths == 1);
        CHECK(passes.passPixels.back() == once.image.pixels);
        for (size_t i = 1; i < passes.passes.size(); ++i) {
            CHECK(passes.passes[i].pass == passes.passes[i - 1].pass + 1);
            CHECK(passes.passes[i].meanPaths > passes.passes[i - 1].meanPaths);
        }
        if (targetError == 0) {
            CHECK(passes.passes.size() == 8);
            CHECK(passes.passes.back().meanPaths == 64);
            CHECK(passes.passes.back().relativeError < passes.passes[4].relativeError);
        }
    }
}

TEST_CASE("progressive: a deadline stops the render with every pixel the mean of its paths", "[render][path]") {
    const scene::SceneDesc desc = litScene(1 << 20, 0);
    ProgressiveRender progressive;
    progressive.deadline = std::chrono::steady_clock::now(); // passed before the first pass
    const Rendered r = renderJob(desc, progressive);
    REQUIRE(r.outcome.ok);
    CHECK(r.outcome.tilesDone == r.outcome.tileCount);
    // The first pass is finished whatever the deadline: one path a pixel, the same as a
    // render of one path a pixel.
    CHECK(r.outcome.stats.fewestPaths == 1);
    CHECK(r.outcome.stats.mostPaths == 1);
    CHECK(r.passes.size() == 1);
    CHECK(r.image.pixels == renderJob(litScene(1, 0), std::nullopt).image.pixels);
}

TEST_CASE("progressive: a deadline ahead lets passes run until it", "[render][path]") {
    const scene::SceneDesc desc = litScene(1 << 20, 0);
    ProgressiveRender progressive;
    const auto start = std::chrono::steady_clock::now();
    progressive.deadline = start + std::chrono::milliseconds(300);
    const Rendered r = renderJob(desc, progressive);
    REQUIRE(r.outcome.ok);
    CHECK(std::chrono::steady_clock::now() >= *progressive.deadline);
    CHECK(r.outcome.stats.fewestPaths >= 1);
    CHECK(r.outcome.stats.mostPaths > 1);
    CHECK(r.outcome.stats.mostPaths < (1 << 20));
    // Unless the deadline fell between passes, the pixels of the stopped pass took up to 16
    // paths more than the others.
    CHECK(r.outcome.stats.mostPaths - r.outcome.stats.fewestPaths <= 16);
}

TEST_CASE("progressive: a cancelled render hands out no tile", "[render][path]") {
    std::atomic<bool> cancel{true};
    RenderJob job;
    job.cancel = &cancel;
    int tiles = 0;
    job.onTileDone = [&](const TileResult&) { ++tiles; };
    job.progressive = ProgressiveRender{};
    const RenderOutcome outcome = render(litScene(64, 0), job);
    CHECK(outcome.cancelled);
    CHECK(!outcome.ok);
    CHECK(tiles == 0);
}

TEST_CASE("progressive: the Whitted integrator renders in one pass as ever", "[render]") {
    scene::SceneDesc desc = litScene(64, 0);
    desc.settings.integrator = scene::Integrator::Whitted;
    const Rendered once = renderJob(desc, std::nullopt);
    const Rendered asked = renderJob(desc, ProgressiveRender{});
    CHECK(asked.image.pixels == once.image.pixels);
    CHECK(asked.passes.empty());
}
