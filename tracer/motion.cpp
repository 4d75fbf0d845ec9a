#include "tracer/motion.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// The two steps around `time` of `count` evenly spaced ones, and how far it is from the
/// first to the second (0 to 1).
struct StepPair {
    size_t first;
    double fraction;
};

StepPair stepsAround(size_t count, double time) {
    if (count < 2) return {0, 0};
    const double at = std::clamp(time, 0.0, 1.0) * static_cast<double>(count - 1);
    const size_t first = std::min(static_cast<size_t>(at), count - 2);
    return {first, at - static_cast<double>(first)};
}

template <typename T>
T linear(const T& a, const T& b, double f) {
    return a + (b - a) * f;
}

} // namespace

std::vector<scene::Modifier> modifiersAt(const std::vector<std::vector<scene::Modifier>>& steps, double time) {
    const StepPair s = stepsAround(steps.size(), time);
    std::vector<scene::Modifier> at = steps[s.first];
    if (s.fraction == 0) return at;
    const std::vector<scene::Modifier>& next = steps[s.first + 1];
    for (size_t i = 0; i < at.size(); ++i) {
        at[i].value = linear(at[i].value, next[i].value, s.fraction);
        at[i].linear = linear(at[i].linear, next[i].linear, s.fraction);
    }
    return at;
}

scene::CameraDesc cameraAt(const std::vector<scene::CameraDesc>& steps, double time) {
    const StepPair s = stepsAround(steps.size(), time);
    scene::CameraDesc at = steps[s.first];
    if (s.fraction == 0) return at;
    const scene::CameraDesc& next = steps[s.first + 1];
    const double f = s.fraction;
    at.position = linear(at.position, next.position, f);
    at.pointing = linear(at.pointing, next.pointing, f);
    at.up = linear(at.up, next.up, f);
    at.fov = linear(at.fov, next.fov, f);
    at.width = linear(at.width, next.width, f);
    at.aperture = linear(at.aperture, next.aperture, f);
    at.focalDistance = linear(at.focalDistance, next.focalDistance, f);
    at.roll = linear(at.roll, next.roll, f);
    return at;
}

TransformPair MovingTransform::at(double time) const {
    const Transform toWorld = outer.compose(Transform::fromModifiers(modifiersAt(*chain, time)));
    return {toWorld, toWorld.inverse()};
}

} // namespace crt::tracer
