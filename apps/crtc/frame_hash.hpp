// A frame's identity for `crtc --continue`: a hash of everything its pixels are made from, so
// that a render is continued only with the frame it began.
#pragma once

#include "interpreter.hpp"
#include "options.hpp"

#include <cstdint>

namespace crt::crtc {

/// Hashes the inputs of frame `scene` of compilation `c` rather than the scene itself (whose
/// JSON takes seconds for a scene of a million spheres): crtc's version, every script file's
/// path and text, the evaluation's options (seed, frame, clock), the size, quality, region and
/// alpha channel the command line asks for, and the path, size and modification time of every image and
/// mesh the scene reads.
uint64_t frameHash(const lang::Compilation& c, const scene::SceneDesc& scene,
                   const Options& options, const tracer::Tile& region);

} // namespace crt::crtc
