// The renderer is deterministic (architecture: "Decisions"): the same scene with depth of field,
// an area light and glossy reflection renders bit-identically with any thread count, every time.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <atomic>
#include <chrono>
#include <thread>
#include <utility>

using namespace crt::tracer;
using namespace crt::tracer::test;

namespace {

SceneDesc stochasticScene() {
    SceneMaker m;
    CameraDesc camera = lookAt({0.4, 1.2, -4}, {0, 0.5, 0}, 45);
    m.desc = blankScene(48, 36, camera);
    m.desc.camera.aperture = 80; // lens radius 0.08 scene units
    m.desc.camera.focalDistance = 3;
    m.desc.camera.apertureShape = ApertureShape::Polygon;
    m.desc.camera.apertureBlades = 5;
    m.desc.settings.dofSamples = 8;
    m.desc.settings.shadowSamples = 6;
    m.desc.settings.glossySamples = 4;
    m.desc.settings.supersampling = 2;
    m.desc.settings.seed = 7;
    m.desc.background = BackgroundDesc{};
    m.desc.background.kind = BackgroundKind::Gradient;
    m.desc.background.horizon = Color{0.8, 0.85, 0.9, 1};
    m.desc.background.sky = Color{0.2, 0.4, 0.9, 1};

    ShadingMaterial floor;
    floor.color = Color{0.6, 0.6, 0.5, 1};
    floor.reflectivity = 0.5;
    floor.diffuse = 0.5;
    floor.glossiness = 0.4;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    ShadingMaterial ball;
    ball.color = Color{0.9, 0.3, 0.2, 1};
    ball.specular = 0.5;
    ball.shininess = 20;
    m.draw(m.sphere({0, 0.6, 0.5}, 0.6, m.material(ball)));
    ShadingMaterial far;
    far.color = Color{0.2, 0.5, 0.9, 1};
    far.reflectivity = 0.3;
    far.diffuse = 0.7;
    far.glossiness = 0.2;
    m.draw(m.sphere({1.3, 0.5, 3}, 0.5, m.material(far)));

    LightDesc area;
    area.kind = LightKind::Area;
    area.origin = {-1, 3, -1};
    area.edgeA = {1.5, 0, 0};
    area.edgeB = {0, 0, 1.5};
    area.color = Color{1, 1, 1, 1};
    m.desc.lights.push_back(area);
    return m.desc;
}

} // namespace

TEST_CASE("Depth of field, area light and glossy reflection render bit-identically on any thread count",
          "[render][determinism]") {
    SceneDesc desc = stochasticScene();
    PixelBuffer reference = renderOk(desc, 1);
    for (int threads : {1, 2, 3, 2}) {
        INFO("threads " << threads);
        PixelBuffer again = renderOk(desc, threads);
        // Float vectors compare element by element; a NaN would fail too, as it should.
        CHECK(again.rgb == reference.rgb);
    }
    // The stochastic features are really in play: a pinhole render of the same scene differs.
    desc.settings.dofSamples = 1;
    CHECK(renderOk(desc, 2).rgb != reference.rgb);
}

TEST_CASE("Changing the seed changes the stochastic samples", "[render][determinism]") {
    SceneDesc desc = stochasticScene();
    PixelBuffer a = renderOk(desc, 2);
    desc.settings.seed = 8;
    CHECK(renderOk(desc, 2).rgb != a.rgb);
}

TEST_CASE("Finished rows are reported once each, in order, with their final values", "[render]") {
    SceneDesc desc = stochasticScene();
    desc.settings.width = 53; // a last tile row and column of 5 pixels
    desc.settings.height = 37;
    const PixelBuffer reference = renderOk(desc, 2);
    for (auto [threads, keepFrame] : {std::pair{1, true}, {3, true}, {1, false}, {3, false}}) {
        INFO("threads " << threads << (keepFrame ? ", frame kept" : ", frame not kept"));
        std::vector<float> streamed;
        int nextRow = 0, calls = 0;
        bool ordered = true;
        RenderSettings settings;
        settings.threads = threads;
        settings.keepFrame = keepFrame;
        settings.onRowsDone = [&](int yBegin, int yEnd, std::span<const float> rgb) {
            ordered = ordered && yBegin == nextRow && yEnd > yBegin &&
                      rgb.size() == std::size_t(yEnd - yBegin) * 53 * 3;
            nextRow = yEnd;
            ++calls;
            streamed.insert(streamed.end(), rgb.begin(), rgb.end());
        };
        RenderOutcome r = renderScene(desc, settings);
        REQUIRE(r.ok);
        CHECK(ordered);
        CHECK(nextRow == 37);
        CHECK(calls == 3); // tile rows of 16, 16 and 5
        CHECK(streamed == reference.rgb);
        // Not kept: the rows went only to the callback, from buffers of their own.
        CHECK(r.frame.rgb.size() == (keepFrame ? reference.rgb.size() : 0));
        CHECK(r.frame.width == 53);
        CHECK(r.frame.height == 37);
    }
}

TEST_CASE("A worker held back for the image module's load joins later; the image is the same", "[render]") {
    SceneDesc desc = stochasticScene();
    PixelBuffer reference = renderOk(desc, 1);
    for (int threads : {1, 2, 3}) {
        INFO("threads " << threads);
        std::atomic<int> calls{0};
        std::atomic<bool> started{false}, startedFirst{true};
        RenderSettings settings;
        settings.threads = threads;
        settings.onThreadsStarted = [&] { started = true; };
        settings.beforeLastWorker = [&] {
            startedFirst = startedFirst && started;
            ++calls;
            std::this_thread::sleep_for(std::chrono::milliseconds(50)); // a load in progress
        };
        RenderOutcome r = renderScene(desc, settings);
        REQUIRE(r.ok);
        CHECK(calls == (threads > 1 ? 1 : 0));
        CHECK(startedFirst);
        CHECK(r.frame.rgb == reference.rgb);
    }
}
