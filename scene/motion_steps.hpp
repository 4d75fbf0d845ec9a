// Motion blur's side of the description: the script's evaluations at the motion steps joined
// into one scene, whose SceneDesc::motion says what moves.
#pragma once

#include "scene/scene_desc.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crt::scene {

/// The times within the shutter (0 at its opening, 1 at its closing) the script is evaluated
/// at: `steps` of them, evenly spaced, the first 0 and the last 1.
double motionStepFraction(int step, int steps);

/// What changed between evaluations that may not: only modifiers and the camera move.
struct MotionConflict {
    SourceSpan where;    ///< what changed (an entity, a light …); its file 0 when unknown
    std::string message; ///< names it and says why that is an error
};

/// Joins `steps`, the evaluations at the motion steps, into `base`, the frame's own: each
/// transform node whose modifiers differ between them moves (base.motion.transforms), and the
/// camera moves when it differs (base.motion.cameras); what is the same at every step and
/// only differs from the frame's own is taken from the steps. Anything else that differs (an
/// entity's shape, material or structure, a light, the background …) is a conflict, and
/// `base` is then left as it was.
std::optional<MotionConflict> joinMotionSteps(SceneDesc& base, const std::vector<SceneDesc>& steps);

} // namespace crt::scene
