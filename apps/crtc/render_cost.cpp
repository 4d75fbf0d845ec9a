// Counting a render's rays from its settings, before tracing.
#include "render_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace crt::crtc {

RenderCost estimateRenderCost(const scene::SceneDesc& scene) {
    const scene::SettingsDesc& s = scene.settings;
    RenderCost cost;
    cost.pixels = static_cast<double>(s.width) * s.height;
    if (s.integrator == scene::Integrator::Path) {
        // Each bounce: the ray on, a shadow ray to each light and one to an emitting surface.
        cost.cameraSamplesPerPixel = s.samples;
        cost.raysPerCameraSample = (s.bounces + 1.0) * (2.0 + static_cast<double>(scene.lights.size()));
        return cost;
    }
    double grid = static_cast<double>(s.supersampling) * s.supersampling;
    if (s.antialias == scene::Antialias::Adaptive || s.antialias == scene::Antialias::ShowAdaptive) {
        // Four samples a region, each region split in four down to aadepth levels.
        grid *= std::pow(4.0, std::max(s.aaDepth, 0) + 1);
    }
    const double lensSamples = scene.camera.aperture > 0 ? std::max(s.dofSamples, 1) : 1;
    cost.cameraSamplesPerPixel = grid * lensSamples;
    double shadowRays = 0;
    for (const scene::LightDesc& light : scene.lights) {
        shadowRays += scene::isExtendedLight(light.kind) ? std::max(s.shadowSamples, 1) : 1;
    }
    const bool glossy = std::any_of(scene.finishes.begin(), scene.finishes.end(),
                                    [](const scene::FinishDesc& f) { return f.glossiness > 0; });
    cost.raysPerCameraSample = (1 + shadowRays) * (glossy ? std::max(s.glossySamples, 1) : 1);
    return cost;
}

std::optional<std::string> renderCostWarning(const scene::SceneDesc& scene) {
    const RenderCost cost = estimateRenderCost(scene);
    if (cost.rays() <= kRaysWorthAWarning) return std::nullopt;
    return fmt::format("crtc: warning: this render traces up to about {:.1e} rays ({}x{} pixels, {:.0f} "
                       "camera samples a pixel, {:.0f} ray(s) a sample with shadows and glossy "
                       "reflections) and may take days; lower the size or the sample counts, or "
                       "try --draft\n",
                       cost.rays(), scene.settings.width, scene.settings.height,
                       cost.cameraSamplesPerPixel, cost.raysPerCameraSample);
}

} // namespace crt::crtc
