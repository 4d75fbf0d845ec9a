// The camera as the preview's HTTP API writes and reads it (docs/preview.md).
#pragma once

#include "scene/scene_desc.hpp"

#include <nlohmann/json.hpp>

namespace crt::crtc::preview {

/// {"position": [x, y, z], "pointing": [...], "up": [...], "fov": f, "roll": r}
nlohmann::json cameraJson(const scene::CameraDesc& camera);

/// `camera` with the fields `json` has (as cameraJson writes them) set; throws
/// std::invalid_argument naming the field when one is not a finite number (or three), or
/// when position and pointing coincide.
scene::CameraDesc cameraFromJson(scene::CameraDesc camera, const nlohmann::json& json);

} // namespace crt::crtc::preview
