// Turbulence: a pattern's point moved by fractal vector noise before the pattern is read.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/ray.hpp"

namespace crt::tracer {

/// `p` moved by desc.displacement (per axis) times a sum of `octaves` octaves of vector
/// noise, each `lambda` times the frequency and `omega` times the amplitude of the last
/// (POV-Ray's turbulence warp, over crt's own noise).
Vec3 turbulentPoint(const Vec3& p, const scene::TextureDesc& desc);

} // namespace crt::tracer
