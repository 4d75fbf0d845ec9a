// crtc's render mode: evaluates each frame, renders it and writes the image(s).
#pragma once

#include "options.hpp"
#include "tracer/renderer.hpp"

#include <cstdint>
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

/// The scene without its time and frame number, as text: two frames with the same key render
/// alike, so the second reuses the first's image.
std::string unchangedFrameKey(const scene::SceneDesc& scene);

/// An animation's frames evaluated and traced elsewhere (each on one process of an MPI job),
/// fed to the run that writes them, in order. The run is crtc's own otherwise: output files,
/// the resume log, progress, the summary and --stats.
struct FedFrame {
    bool ok = false;        ///< evaluated without errors (the feed has said why not)
    bool unchanged = false; ///< the same scene as the frame before: its image is reused
    int width = 0, height = 0;
    double gamma = 1.0;
    bool srgb = false;
    uint64_t hash = 0; ///< frameHash for the resume log
};
class FrameFeed {
  public:
    virtual ~FrameFeed() = default;
    /// Before the first frame: which frames an interrupted run finished, so that they are
    /// not traced again (`frame`, its frameHash).
    virtual void begin(std::function<bool(int frame, uint64_t hash)> finishedBefore) = 0;
    /// The next frame of the run, once it is evaluated; frames come in order.
    virtual FedFrame next(int frame) = 0;
    /// The tiles of `job` of the frame next() returned last, once they are traced.
    virtual tracer::RenderOutcome render(const tracer::RenderJob& job) = 0;
};
/// renderCommand with its frames from `feed`.
int renderFedFrames(const Options& options, FrameFeed& feed);

/// The default output path: the script's path with .png (.gif for an animation).
std::string defaultOutput(const std::string& script, bool animation);
/// Whether an output name has a printf-style frame number (%d, %04d …).
bool hasFramePattern(const std::string& output);
/// The output name with the frame number substituted for its pattern.
std::string numberedOutput(const std::string& output, int frame);

} // namespace crt::crtc
