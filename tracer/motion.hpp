// What moves while the shutter is open (motion blur): transforms and the camera at a time
// within the shutter, each value linear between the motion steps around it
// (scene::MotionDesc).
#pragma once

#include "tracer/transform.hpp"
#include "scene/scene_desc.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// The modifiers at `time` (0: the shutter opens, 1: it closes) of a list given at each of
/// evenly spaced steps (the same kinds at every step).
std::vector<scene::Modifier> modifiersAt(const std::vector<std::vector<scene::Modifier>>& steps, double time);
/// The camera at `time` of one given at each of evenly spaced steps.
scene::CameraDesc cameraAt(const std::vector<scene::CameraDesc>& steps, double time);

/// A transform that changes while the shutter is open: `outer`, which stays, after the
/// modifiers of a chain of transform nodes at least one of which moves, given at every step
/// (each step's list applied left to right: the innermost node's modifiers first).
struct MovingTransform {
    Transform outer;
    std::shared_ptr<const std::vector<std::vector<scene::Modifier>>> chain;

    TransformPair at(double time) const;
};

} // namespace crt::tracer
