// What the camera sees at one point of the image: the entity a camera ray meets first, for
// tools that name the object under the mouse.
#pragma once

#include "scene/scene_desc.hpp"

#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace crt::tracer {

/// The nearest surface along the pinhole camera ray through one image point.
struct PickResult {
    bool hit = false;
    int32_t entity = -1; ///< the SceneDesc entity of the surface (a primitive, not a CSG node)
    /// The SceneDesc material it is drawn with (its own or given); -1: the default.
    int32_t material = -1;
    double distance = 0; ///< along the ray, in world units per unit of ray direction
    glm::dvec3 point{0.0};
};

/// Traces the camera ray through (x, y), in pixels from the top left of the scene's
/// settings' width × height image. Nothing when the scene cannot be built (`error` says why,
/// as render() would).
std::optional<PickResult> pick(const scene::SceneDesc& scene, double x, double y, std::string& error);

} // namespace crt::tracer
