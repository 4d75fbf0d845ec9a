// The preview's passes: what each renders, and the size of a drag's frames.
#include "preview/render_plan.hpp"

#include <catch2/catch.hpp>

using namespace crt;
using namespace crt::crtc::preview;

TEST_CASE("refinement goes from an eighth of the size to the script's own quality", "[preview]") {
    const std::vector<RenderPass> passes = refinementPasses({false, 1});
    REQUIRE(passes.size() == 4);
    CHECK(passes[0].scale == 0.125);
    CHECK(passes[1].scale == 0.5);
    CHECK((passes[2].scale == 1 && passes[2].draft));
    CHECK((passes[3].scale == 1 && !passes[3].draft));
    const std::vector<RenderPass> draft = refinementPasses({true, 0.5});
    REQUIRE(draft.size() == 3);
    CHECK((draft.back().scale == 0.5 && draft.back().draft));
}

TEST_CASE("a draft pass samples once and keeps the scene's camera otherwise", "[preview]") {
    scene::SceneDesc scene;
    scene.settings.width = 801;
    scene.settings.height = 600;
    scene.settings.shadowSamples = 16;
    scene.settings.dofSamples = 8;
    scene.camera.aperture = 2;
    const scene::SceneDesc draft = passScene(scene, {0.5, true});
    CHECK(draft.settings.width == 401);
    CHECK(draft.settings.height == 300);
    CHECK(draft.settings.shadowSamples == 1);
    CHECK(draft.camera.aperture == 0);
    CHECK(passBudget({0.5, true}).grid == 1);
    const scene::SceneDesc full = passScene(scene, {1, false});
    CHECK(full.settings.shadowSamples == 16);
    CHECK(full.camera.aperture == 2);
    CHECK(passBudget({1, false}).grid == 0);
    CHECK(passScene(scene, {1e-6, true}).settings.width == 1);
}

TEST_CASE("a drag's frames shrink when slow and grow when quick, within bounds", "[preview]") {
    CHECK(nextDragFraction(0.5, 0.2) == Approx(0.25));      // four times too slow: half the side
    CHECK(nextDragFraction(0.25, 0.0125) == Approx(0.5));   // four times quicker than needed
    CHECK(nextDragFraction(0.5, 0.01) == 0.5);              // never above half the size
    CHECK(nextDragFraction(0.125, 10) == 0.125);            // nor below an eighth
    CHECK(nextDragFraction(0.3, 0) == 0.3);
}
