// The scene description as JSON; the format is documented in
// docs/scene-json.md and versioned by SceneDesc::kSchemaVersion.
#pragma once

#include "scene/scene_desc.hpp"

#include <string>

namespace crt::scene {

std::string sceneToJson(const SceneDesc& scene, int indent = 2);
/// Entity `id` of the scene as the scene JSON's "entities" holds it, on one line.
std::string entityToJson(const SceneDesc& scene, size_t id);

} // namespace crt::scene
