// The preview's render passes (see render_plan.hpp).
#include "preview/render_plan.hpp"

#include <algorithm>
#include <cmath>

namespace crt::crtc::preview {

std::vector<RenderPass> refinementPasses(const ViewQuality& quality) {
    std::vector<RenderPass> passes{{quality.scale / 8, true}, {quality.scale / 2, true}, {quality.scale, true}};
    if (!quality.draft) passes.push_back({quality.scale, false});
    return passes;
}

RenderPass interactivePass(const ViewQuality& quality, double fraction) { return {quality.scale * fraction, true}; }

double nextDragFraction(double fraction, double seconds) {
    constexpr double kFrameSeconds = 1.0 / 20;
    if (!(seconds > 0)) return fraction;
    return std::clamp(fraction * std::sqrt(kFrameSeconds / seconds), 1.0 / 8, 0.5);
}

scene::SceneDesc passScene(const scene::SceneDesc& scene, const RenderPass& pass) {
    scene::SceneDesc desc = scene;
    scene::SettingsDesc& s = desc.settings;
    s.width = std::max(1, static_cast<int>(std::lround(s.width * pass.scale)));
    s.height = std::max(1, static_cast<int>(std::lround(s.height * pass.scale)));
    if (pass.draft) {
        desc.camera.aperture = 0;
        s.dofSamples = 1;
        s.samples = 1;
        s.shadowSamples = 1;
        s.glossySamples = 1;
    }
    return desc;
}

tracer::SampleBudget passBudget(const RenderPass& pass) { return {pass.draft ? 1 : 0}; }

} // namespace crt::crtc::preview
