// A pattern: a number field over texture space, read through a colour map (spec: Textures).
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/ray.hpp"

namespace crt::tracer {

/// The value of `desc`'s pattern at a point of texture space, where the surface's world-space
/// unit normal is `normal` (Slope reads it): turbulence first, then the pattern, then
/// frequency, phase and waveform. Continuous patterns give a value in [0, 1]; discrete ones
/// (scene::isDiscretePattern) the position of their colour: 0, 1 or 2.
double patternValue(const scene::TextureDesc& desc, const Vec3& p,
                    const Vec3& normal = Vec3(0, 1, 0));

} // namespace crt::tracer
