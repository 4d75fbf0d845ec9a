// Render quality chosen outside the script (crtc's --supersampling, --draft, ...): applied to
// an evaluated scene, so the script itself never changes.
#pragma once

#include "scene/scene_desc.hpp"

#include <optional>

namespace crt::scene {

struct QualityOverrides {
    /// One camera sample a pixel, no depth of field, one shadow and one glossy sample: a quick
    /// look at a scene. The counts below, when given, win over it.
    bool draft = false;
    std::optional<int> supersampling;
    std::optional<int> dofSamples;
    std::optional<int> shadowSamples;
    std::optional<int> glossySamples;
    std::optional<Antialias> antialias;
    std::optional<Integrator> integrator;
    std::optional<int> samples; ///< paths a pixel (the path integrator's)
    std::optional<double> targetError;

    bool any() const {
        return draft || supersampling || dofSamples || shadowSamples || glossySamples || antialias ||
               integrator || samples || targetError;
    }
};

/// `scene` with the quality of `overrides`.
void applyQuality(SceneDesc& scene, const QualityOverrides& overrides);

} // namespace crt::scene
