// Reads the images a scene uses (panorama, image textures) before rendering starts.
#pragma once

#include "tracer/image.hpp"
#include "scene/scene_desc.hpp"

#include <map>
#include <string>

namespace crt::tracer {

struct SceneImages {
    std::map<std::string, Image> byPath;

    const Image* find(const std::string& path) const {
        auto it = byPath.find(path);
        return it == byPath.end() ? nullptr : &it->second;
    }
};

/// Reads every image the scene refers to; 8-bit images are decoded from sRGB unless the
/// scene's gamma is 1.0, when raw/255 is used (as the original). False with `error` set
/// ("<script>:<line>:<col>: error: cannot read <file>: <cause>") when one cannot be read, or is
/// larger than the scene's limits allow (RenderLimits::maxImagePixels).
bool loadSceneImages(const scene::SceneDesc& desc, SceneImages& images, std::string& error);

} // namespace crt::tracer
