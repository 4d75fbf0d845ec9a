// The preview's mouse camera (see camera_controls.hpp).
#include "preview/camera_controls.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace crt::crtc::preview {

namespace {

using glm::dvec3;

/// The unit up vector of the camera; +y when its own is zero.
dvec3 unitUp(const scene::CameraDesc& camera) {
    double length = glm::length(camera.up);
    return length > 0 ? camera.up / length : dvec3(0, 1, 0);
}

/// `v` turned by `radians` about the unit `axis` (Rodrigues).
dvec3 rotated(const dvec3& v, const dvec3& axis, double radians) {
    double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1 - c);
}

/// The angle between `v` and the unit `up`, in radians.
double angleFromUp(const dvec3& v, const dvec3& up) {
    return std::acos(std::clamp(glm::dot(glm::normalize(v), up), -1.0, 1.0));
}

} // namespace

scene::CameraDesc orbit(scene::CameraDesc camera, double yawDegrees, double pitchDegrees) {
    const dvec3 up = unitUp(camera);
    dvec3 offset = camera.position - camera.pointing; // from the pointing point to the camera
    if (glm::length(offset) == 0) return camera;
    offset = rotated(offset, up, glm::radians(-yawDegrees));
    // Pitch about the horizontal axis of the view, stopping short of either pole.
    dvec3 side = glm::cross(up, offset);
    if (glm::length(side) > 0) {
        const double margin = glm::radians(1.0);
        const double now = angleFromUp(offset, up);
        const double wanted = std::clamp(now - glm::radians(pitchDegrees), margin, glm::pi<double>() - margin);
        offset = rotated(offset, glm::normalize(side), wanted - now); // about up × offset: away from up
    }
    camera.position = camera.pointing + offset;
    return camera;
}

scene::CameraDesc pan(scene::CameraDesc camera, double right, double up) {
    const dvec3 forward = camera.pointing - camera.position;
    const double distance = glm::length(forward);
    if (distance == 0) return camera;
    // The camera's right and up, as the renderer's left-handed camera has them.
    dvec3 side = glm::cross(unitUp(camera), forward);
    if (glm::length(side) == 0) return camera;
    side = glm::normalize(side);
    const dvec3 viewUp = glm::normalize(glm::cross(forward, side));
    const double viewHeight = 2 * distance * std::tan(glm::radians(camera.fov) / 2);
    const dvec3 shift = (side * -right + viewUp * -up) * viewHeight;
    camera.position += shift;
    camera.pointing += shift;
    return camera;
}

scene::CameraDesc dolly(scene::CameraDesc camera, double factor) {
    const dvec3 offset = camera.position - camera.pointing;
    const double distance = glm::length(offset);
    if (distance == 0 || !(factor > 0)) return camera;
    const double wanted = std::max({distance * factor, distance * 1e-6, 1e-6});
    camera.position = camera.pointing + offset * (wanted / distance);
    return camera;
}

scene::CameraDesc withFov(scene::CameraDesc camera, double fovDegrees) {
    if (std::isfinite(fovDegrees)) camera.fov = std::clamp(fovDegrees, 1.0, 170.0);
    return camera;
}

} // namespace crt::crtc::preview
