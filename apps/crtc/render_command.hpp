// crtc's render mode: evaluates each frame, renders it and writes the image(s).
#pragma once

#include "options.hpp"

#include <functional>
#include <string>

namespace crt::crtc {

/// Evaluates one frame into a compilation, printing its diagnostics; returns false on errors.
using CompileFrame = std::function<bool(int frame, lang::Compilation& out)>;

/// Renders the selected frames and writes the output; returns crtc's exit status. Under
/// mpirun, the processes of the job share the work (distributed/distributed_render.hpp).
int renderCommand(const Options& options, const CompileFrame& compileFrame);

/// Traces the tiles of a job: tracer::render, or a render shared out with other processes.
using TileRenderer =
    std::function<tracer::RenderOutcome(const scene::SceneDesc&, const tracer::RenderJob&)>;
/// Traces a job's tiles in this process (tracer::render; nothing for a job without tiles).
tracer::RenderOutcome renderTilesHere(const scene::SceneDesc& scene, const tracer::RenderJob& job);
/// renderCommand in this process, its tiles traced by `renderTiles`.
int renderFrames(const Options& options, const CompileFrame& compileFrame,
                 const TileRenderer& renderTiles);
/// Applies the command line's size and quality to an evaluated scene.
void applyCommandLine(const Options& options, scene::SceneDesc& scene);

/// The default output path: the script's path with .png (.gif for an animation).
std::string defaultOutput(const std::string& script, bool animation);
/// Whether an output name has a printf-style frame number (%d, %04d …).
bool hasFramePattern(const std::string& output);
/// The output name with the frame number substituted for its pattern.
std::string numberedOutput(const std::string& output, int frame);

} // namespace crt::crtc
