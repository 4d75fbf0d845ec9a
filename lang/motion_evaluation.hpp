// Motion blur in the front end: with the shutter open, the script is evaluated again at each
// motion step across it, and the evaluations are joined into the frame's scene
// (scene/motion_steps.hpp says what may move).
#pragma once

#include "interpreter.hpp"

namespace crt::lang {

/// When `c` evaluated without errors to a scene whose shutter is open: evaluates the script at
/// Settings.motionsteps times across the shutter and joins them into c.scene. An evaluation
/// with errors, or a change that is not a motion, is an error of `c` (and c.scene is dropped).
void evaluateMotionSteps(Compilation& c, const EvalOptions& options);

} // namespace crt::lang
