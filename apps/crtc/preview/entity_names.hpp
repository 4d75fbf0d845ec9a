// Names the scene's entities for people: their kind and where the script built them.
#pragma once

#include "scene/scene_desc.hpp"

#include <string>

namespace crt::crtc::preview {

/// The entity's kind as a script spells it: "Sphere", "Box", … "union", "group".
std::string entityKind(const scene::EntityDesc& entity);

/// The drawn root (an index of scene.drawn's entities) whose graph holds `entity`; -1 if none.
int32_t drawnRootOf(const scene::SceneDesc& scene, int32_t entity);

} // namespace crt::crtc::preview
