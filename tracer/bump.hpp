// Bump mapping: the shading normal tilted by the gradient of a bump texture's height field.
#pragma once

#include "tracer/render_scene.hpp"
#include "tracer/texture.hpp"

namespace crt::tracer {

/// The unit shading normal `n` (either orientation) tilted against the surface gradient of
/// `bump`'s height at `si`, scaled by the bump's strength: n − 0.1·strength·∇h, normalised.
/// Heights read from uv are differentiated in uv and carried onto the surface along its
/// tangents (si.dpdu, si.dpdv); heights read from the point, in object space.
Vec3 bumpedNormal(const Texture& bump, const SurfaceInteraction& si, const Vec3& n);

} // namespace crt::tracer
