// The scene description as JSON (crtc --dump-scene); the format is documented in
// docs/scene-json.md and versioned by SceneDesc::kSchemaVersion.
#pragma once

#include "tracer/scene_desc.hpp"

#include <string>

namespace crt::lang {

std::string sceneToJson(const tracer::SceneDesc& scene, int indent = 2);

} // namespace crt::lang
