// An estimate of a render's work before it starts: a script may ask for 10^15 rays, which
// no machine finishes, and saying so up front beats a silent run.
#pragma once

#include "scene/scene_desc.hpp"

#include <optional>
#include <string>

namespace crt::crtc {

/// Above this many estimated rays a render is worth a warning (about a day on a desktop).
inline constexpr double kRaysWorthAWarning = 1e11;

struct RenderCost {
    double pixels = 0;
    double cameraSamplesPerPixel = 0; ///< supersampling² (adaptive at its deepest) × lens samples
    double raysPerCameraSample = 0;   ///< the first hit's fan-out: shadow and glossy rays
    double rays() const { return pixels * cameraSamplesPerPixel * raysPerCameraSample; }
};

/// The work `scene` asks for, counting the most its settings allow (adaptive antialiasing
/// subdividing everywhere, every light's shadow rays, glossy rays at every hit).
RenderCost estimateRenderCost(const scene::SceneDesc& scene);

/// A warning naming the estimate and what drives it, if it is above kRaysWorthAWarning.
std::optional<std::string> renderCostWarning(const scene::SceneDesc& scene);

} // namespace crt::crtc
