// The heights of a scene's HeightField: read from its image, or sampled from its Function.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/height_field.hpp"

#include <memory>
#include <string>

namespace crt::tracer {

/// The grid of `desc`: its image's pixels (the first row at z = 1), each height as POV-Ray
/// reads one, or its function at resolution × resolution points, held to [0, 1]; with normals
/// when smooth. Null with `error` set (the image cannot be read, or is larger than `limits`
/// allow).
std::shared_ptr<const HeightGrid> readHeightGrid(const scene::HeightFieldDesc& desc,
                                                 const scene::RenderLimits& limits, std::string& error);

} // namespace crt::tracer
