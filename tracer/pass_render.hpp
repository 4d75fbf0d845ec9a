// A progressive path-traced render (RenderJob::progressive): passes over the tiles, each
// adding paths to every pixel, the running sums of every pixel kept between them.
#pragma once

#include "tracer/pixel_sampler.hpp"
#include "tracer/renderer.hpp"

#include <vector>

namespace crt::tracer {

/// Traces `tiles` of a `width` × `height` image in passes on `threads` threads until every
/// pixel is settled, the job's deadline passes or the job is cancelled; unless cancelled, then
/// hands each tile to the job's onTileDone once. `stats` gets one thread's counters each (and
/// the first, every pixel's paths). Returns the tiles handed out.
int renderInPasses(const PixelSampler& sampler, const std::vector<Tile>& tiles, const RenderJob& job, int width,
                   int height, std::vector<RayStats>& stats);

} // namespace crt::tracer
