// The scene description as JSON; the format is documented in
// docs/scene-json.md and versioned by SceneDesc::kSchemaVersion.
#pragma once

#include "scene/scene_desc.hpp"

#include <string>

namespace crt::scene {

std::string sceneToJson(const SceneDesc& scene, int indent = 2);

} // namespace crt::scene
