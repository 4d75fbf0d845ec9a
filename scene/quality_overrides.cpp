// Render quality chosen outside the script.
#include "scene/quality_overrides.hpp"

namespace crt::scene {

void applyQuality(SceneDesc& scene, const QualityOverrides& overrides) {
    SettingsDesc& s = scene.settings;
    if (overrides.draft) {
        s.supersampling = 1;
        s.samples = 1;
        s.antialias = Antialias::Grid;
        s.dofSamples = 1;
        scene.camera.aperture = 0; // a pinhole: one lens sample would only add noise
        s.shadowSamples = 1;
        s.glossySamples = 1;
    }
    if (overrides.supersampling) s.supersampling = *overrides.supersampling;
    if (overrides.dofSamples) s.dofSamples = *overrides.dofSamples;
    if (overrides.shadowSamples) s.shadowSamples = *overrides.shadowSamples;
    if (overrides.glossySamples) s.glossySamples = *overrides.glossySamples;
    if (overrides.antialias) s.antialias = *overrides.antialias;
    if (overrides.integrator) s.integrator = *overrides.integrator;
    if (overrides.samples) s.samples = *overrides.samples;
    if (overrides.targetError) s.targetError = *overrides.targetError;
}

} // namespace crt::scene
