// Renders a SceneDesc into linear RGB pixels: tiles handed to std::thread workers.
#pragma once

#include "tracer/scene_desc.hpp"
#include "tracer/stats.hpp"

#include <atomic>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace crt::tracer {

/// Linear RGB floats, row-major, top row first.
struct PixelBuffer {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

struct RenderSettings {
    int threads = 0;                          ///< 0: all cores
    const std::atomic<bool>* cancel = nullptr; ///< set (e.g. by SIGINT) to stop early
    /// Called from the calling thread about ten times a second with finished/total tiles.
    std::function<void(int done, int total)> onProgress;
    /// Called with rows [yBegin, yEnd) of the image (RGB floats) as soon as they are final,
    /// in order from the top, one call at a time, from a worker thread: it should only copy
    /// them and hand them over (to an image file being written while the render goes on).
    std::function<void(int yBegin, int yEnd, std::span<const float> rgb)> onRowsDone;
    /// False (with onRowsDone): the rows go only to onRowsDone, and RenderOutcome::frame
    /// comes back with its size but no pixels. The render then holds only the rows in
    /// flight: for an image streamed to a file that nobody reads back.
    bool keepFrame = true;
    /// Called once all the render's threads have been created, before the calling thread
    /// starts tracing (crtc starts loading the image module then; see image_io::startLoading).
    std::function<void()> onThreadsStarted;
    /// With two or more threads, one of them calls this (after onThreadsStarted) before it
    /// starts tracing and may be held up by it: crtc holds it until the image module, which
    /// keeps a core busy while it loads, is loaded. The load then has a core of its own
    /// instead of a share of every core, and ends before the render rather than after it.
    std::function<void()> beforeLastWorker;
};

struct RenderOutcome {
    bool ok = false;
    bool cancelled = false;
    std::string error; ///< why it failed, e.g. "scene.obj:12: bad vertex index"
    PixelBuffer frame;
    RayStats stats;
    double buildSeconds = 0;  ///< scene build: BVH, images, textures
    double renderSeconds = 0; ///< tracing
    size_t primitives = 0;
    size_t bvhNodes = 0;
    int bvhDepth = 0;
    uint64_t samples = 0; ///< camera samples per pixel (before DOF)
};

/// Renders `desc` at its settings' width and height.
RenderOutcome renderScene(const SceneDesc& desc, const RenderSettings& settings);

} // namespace crt::tracer
