// The renderer is deterministic (architecture: "Decisions"): the same scene with depth of field,
// an area light and glossy reflection renders bit-identically with any thread count, every time.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <atomic>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

scene::SceneDesc stochasticScene() {
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0.4, 1.2, -4}, {0, 0.5, 0}, 45);
    m.desc = blankScene(48, 36, camera);
    m.desc.camera.aperture = 80; // lens radius 0.08 scene units
    m.desc.camera.focalDistance = 3;
    m.desc.camera.apertureShape = scene::ApertureShape::Polygon;
    m.desc.camera.apertureBlades = 5;
    m.desc.settings.dofSamples = 8;
    m.desc.settings.shadowSamples = 6;
    m.desc.settings.glossySamples = 4;
    m.desc.settings.supersampling = 2;
    m.desc.settings.seed = 7;
    m.desc.background = scene::BackgroundDesc{};
    m.desc.background.kind = scene::BackgroundKind::Gradient;
    m.desc.background.horizon = scene::Color{0.8, 0.85, 0.9, 1};
    m.desc.background.sky = scene::Color{0.2, 0.4, 0.9, 1};

    ShadingMaterial floor;
    floor.color = scene::Color{0.6, 0.6, 0.5, 1};
    floor.reflectivity = 0.5;
    floor.diffuse = 0.5;
    floor.glossiness = 0.4;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    ShadingMaterial ball;
    ball.color = scene::Color{0.9, 0.3, 0.2, 1};
    ball.specular = 0.5;
    ball.shininess = 20;
    m.draw(m.sphere({0, 0.6, 0.5}, 0.6, m.material(ball)));
    ShadingMaterial far;
    far.color = scene::Color{0.2, 0.5, 0.9, 1};
    far.reflectivity = 0.3;
    far.diffuse = 0.7;
    far.glossiness = 0.2;
    m.draw(m.sphere({1.3, 0.5, 3}, 0.5, m.material(far)));

    scene::LightDesc area;
    area.kind = scene::LightKind::Area;
    area.origin = {-1, 3, -1};
    area.edgeA = {1.5, 0, 0};
    area.edgeB = {0, 0, 1.5};
    area.color = scene::Color{1, 1, 1, 1};
    m.desc.lights.push_back(area);
    return m.desc;
}

} // namespace

TEST_CASE("Depth of field, area light and glossy reflection render bit-identically on any thread count",
          "[render][determinism]") {
    scene::SceneDesc desc = stochasticScene();
    PixelBuffer reference = renderOk(desc, 1);
    for (int threads : {1, 2, 3, 2}) {
        INFO("threads " << threads);
        PixelBuffer again = renderOk(desc, threads);
        // Float vectors compare element by element; a NaN would fail too, as it should.
        CHECK(again.pixels == reference.pixels);
    }
    // The stochastic features are really in play: a pinhole render of the same scene differs.
    desc.settings.dofSamples = 1;
    CHECK(renderOk(desc, 2).pixels != reference.pixels);
}

TEST_CASE("Changing the seed changes the stochastic samples", "[render][determinism]") {
    scene::SceneDesc desc = stochasticScene();
    PixelBuffer a = renderOk(desc, 2);
    desc.settings.seed = 8;
    CHECK(renderOk(desc, 2).pixels != a.pixels);
}

TEST_CASE("Any set of tiles renders the same pixels as the whole image", "[render][determinism]") {
    scene::SceneDesc desc = stochasticScene();
    desc.settings.width = 53; // a last tile column of 5 pixels and a last tile row of 4
    desc.settings.height = 36;
    const PixelBuffer whole = renderOk(desc, 2);
    // Tiles of another size, given in reverse: each is reported once, with the same values
    // the whole image has there.
    std::vector<Tile> tiles = imageTiles(53, 36, 7);
    REQUIRE(tiles.size() == 48);
    CHECK(tiles.back() == Tile{49, 35, 53, 36});
    std::reverse(tiles.begin(), tiles.end());
    const std::vector<Tile> region(tiles.begin(), tiles.begin() + 10); // the bottom right
    for (int threads : {1, 3}) {
        INFO("threads " << threads);
        RenderJob job;
        job.tiles = region;
        job.threads = threads;
        std::vector<int> seen(region.size(), 0);
        bool matches = true;
        job.onTileDone = [&](const TileResult& r) {
            ++seen[static_cast<size_t>(r.index)];
            matches = matches && r.tile == region[static_cast<size_t>(r.index)] &&
                      r.pixels.size() == static_cast<size_t>(r.tile.width() * r.tile.height() * 3);
            for (int y = r.tile.y0; y < r.tile.y1 && matches; ++y)
                for (int x = r.tile.x0; x < r.tile.x1; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const size_t at = static_cast<size_t>((y - r.tile.y0) * r.tile.width() + x - r.tile.x0) * 3 + c;
                        matches = matches && r.pixels[at] == whole.pixels[(static_cast<size_t>(y) * 53 + x) * 3 + c];
                    }
        };
        RenderOutcome outcome = render(desc, job);
        REQUIRE(outcome.ok);
        CHECK(outcome.tilesDone == 10);
        CHECK(outcome.tileCount == 10);
        CHECK(matches);
        CHECK(seen == std::vector<int>(region.size(), 1));
    }
}

TEST_CASE("A sample budget replaces the scene's anti-aliasing", "[render]") {
    scene::SceneDesc desc = stochasticScene(); // a 2 x 2 grid
    desc.settings.dofSamples = 1;
    const PixelBuffer fine = renderOk(desc, 2);
    desc.settings.supersampling = 1;
    const PixelBuffer single = renderOk(desc, 2);
    REQUIRE(fine.pixels != single.pixels);
    desc.settings.supersampling = 2;
    desc.settings.antialias = scene::Antialias::Adaptive;
    RenderJob job;
    job.samples.grid = 1;
    PixelBuffer budgeted(desc.settings.width, desc.settings.height);
    job.onTileDone = [&](const TileResult& r) { budgeted.place(r); };
    RenderOutcome outcome = render(desc, job);
    REQUIRE(outcome.ok);
    CHECK(outcome.samples == 1);
    CHECK(budgeted.pixels == single.pixels);
}

TEST_CASE("A cancelled render starts no further tile", "[render]") {
    scene::SceneDesc desc = stochasticScene();
    std::atomic<bool> cancel{false};
    RenderJob job;
    job.threads = 1;
    job.cancel = &cancel;
    int reported = 0;
    job.onTileDone = [&](const TileResult&) {
        if (++reported == 2) cancel = true;
    };
    RenderOutcome outcome = render(desc, job);
    CHECK_FALSE(outcome.ok);
    CHECK(outcome.cancelled);
    CHECK(outcome.tilesDone == 2);
    CHECK(reported == 2);
    CHECK(outcome.tileCount == 9); // 48 x 36 in tiles of 16: 3 x 3
}

TEST_CASE("A tile outside the image is an error, not a crash", "[render]") {
    scene::SceneDesc desc = stochasticScene(); // 48 x 36
    for (Tile bad : {Tile{40, 30, 49, 36}, Tile{-1, 0, 8, 8}, Tile{8, 8, 8, 16}, Tile{0, 30, 16, 37}}) {
        RenderJob job;
        job.tiles = {Tile{0, 0, 16, 16}, bad};
        int reported = 0;
        job.onTileDone = [&](const TileResult&) { ++reported; };
        RenderOutcome outcome = render(desc, job);
        CHECK_FALSE(outcome.ok);
        CHECK_FALSE(outcome.cancelled);
        CHECK(outcome.error.find("is not inside the 48x36 image") != std::string::npos);
        CHECK(reported == 0);
    }
}
