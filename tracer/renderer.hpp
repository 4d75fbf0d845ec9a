// Renders a scene description: tiles of the image traced by std::thread workers, each finished
// tile handed to the caller.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/aov.hpp"
#include "tracer/stats.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace crt::tracer {

/// A rectangle of the image: columns [x0, x1) of rows [y0, y1), row 0 at the top.
struct Tile {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool operator==(const Tile&) const = default;
};

/// The side of the tiles imageTiles cuts an image into by default.
inline constexpr int kTileSize = 16;

/// `region` cut into square tiles of `size` pixels from its top left corner (narrower at the
/// right edge, shorter at the bottom), row by row from the top.
std::vector<Tile> regionTiles(const Tile& region, int size = kTileSize);
/// A whole `width` × `height` image cut into tiles, as regionTiles.
std::vector<Tile> imageTiles(int width, int height, int size = kTileSize);

/// The cores this process may run on: its CPU affinity (set by taskset, by mpirun's binding, by
/// Slurm's CPUs per task), else every core. The default number of render threads.
unsigned availableCores();

/// A finished tile: its linear RGB floats (and premultiplied alpha with RenderJob::alpha),
/// row-major from its top row.
struct TileResult {
    Tile tile;
    int index = 0;                ///< its place in RenderJob::tiles
    int channels = 3;             ///< 4 with RenderJob::alpha
    std::span<const float> pixels; ///< tile.width() × tile.height() × channels values
};

/// The camera samples a pixel gets.
struct SampleBudget {
    /// 0: as the scene's settings say (grid or adaptive anti-aliasing); n > 0: an n × n grid
    /// (n² paths under the path integrator), whatever the scene asks for (a quick preview's 1).
    int grid = 0;
};

struct PixelBuffer;

/// The image after a pass of a progressive render.
struct PassImage {
    int pass = 0;                        ///< from 1
    double meanPaths = 0;                ///< the paths a pixel has taken so far, on average
    double relativeError = 0;            ///< the image's estimated relative error so far
    const PixelBuffer* image = nullptr; ///< the whole image, the job's tiles filled in
};

/// A path-traced render in passes, each adding paths to every pixel that has not reached its
/// target error or its `samples` (1, 2, 4, 8 and 16 paths in all after the first five passes,
/// then 16 more a pass): an image exists early and improves until it is done. Each pixel
/// takes its paths in the same order as in a render in one pass, so a finished progressive
/// render is the same bits as that render.
struct ProgressiveRender {
    /// Once it has passed (and the first pass is done) no further tile is started: each pixel
    /// is then the mean of the paths it took.
    std::optional<std::chrono::steady_clock::time_point> deadline;
    /// Called after each pass, from the thread that called render().
    std::function<void(const PassImage&)> onPass;
};

/// What to render of a scene, and how.
struct RenderJob {
    /// The region to render, tiles inside the image; empty: the whole image (imageTiles).
    std::vector<Tile> tiles;
    SampleBudget samples;
    int threads = 0;                           ///< 0: availableCores()
    const std::atomic<bool>* cancel = nullptr; ///< once set, no further tile is started
    /// Called once for every finished tile, from the worker that traced it, one call at a time;
    /// `rgb` is valid during the call only. A tile's pixels do not depend on which thread traced
    /// it, nor on the other tiles of the job: the same tile of the same scene is the same bits.
    std::function<void(const TileResult&)> onTileDone;
    /// Which tile a worker traces next: an index into `tiles`, or -1 when it should stop. Empty:
    /// every tile once, in order. Lets the caller share the tiles out with other processes
    /// while the render goes on; it is called from the workers, concurrently, and may block.
    std::function<int()> nextTile;
    /// A fourth channel, alpha: the share of a pixel's camera rays that meet the scene. The
    /// background is then transparent (a ray that meets nothing counts as black), so the color
    /// is premultiplied by alpha. Without it, the same RGB bits as before.
    bool alpha = false;
    /// Under the path integrator: render in passes, the tiles handed to onTileDone at the end.
    /// Not with `nextTile`. Ignored under the Whitted integrator.
    std::optional<ProgressiveRender> progressive;
    /// Under the path integrator: buffers written after each pixel's colour in its tile
    /// (writePathPixel); an error under the Whitted integrator.
    AovSet aovs;

    /// Whether the caller has asked it to stop.
    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
    /// Floats a pixel of the tiles: RGB, alpha, the AOVs.
    int channels() const { return tileChannels(alpha, aovs); }
    int colorChannels() const { return tileChannels(alpha, {}); }
};

struct RenderOutcome {
    bool ok = false;
    bool cancelled = false;
    std::string error; ///< why it failed, e.g. "scene.obj:12: bad vertex index"
    int tilesDone = 0;
    int tileCount = 0;
    RayStats stats;
    double buildSeconds = 0;  ///< scene build: BVH, images, textures
    double renderSeconds = 0; ///< tracing
    uint64_t primitives = 0;      ///< stored: RenderScene::storedPrimitives
    uint64_t drawnPrimitives = 0; ///< drawn: a mesh or an instance of a shared entity is one
    uint64_t sceneBytes = 0;     ///< what the render scene holds (RenderScene::byteSize)
    uint64_t peakBytes = 0;      ///< the process's peak resident memory when the render ended
    size_t bvhNodes = 0;
    int bvhDepth = 0;
    uint64_t samples = 0; ///< camera samples per pixel (before depth of field)
    std::string shading;  ///< the shading the scene uses (SceneFeatures::names)
    /// What the render met that the user should hear of, a line each ("scene.crt:3:5: warning:
    /// …"): an isosurface's function steeper than its maxgradient, say.
    std::string warnings;
};

/// Renders the tiles of `job` of `scene` at its settings' width and height.
RenderOutcome render(const scene::SceneDesc& scene, const RenderJob& job);

/// Linear floats of a whole image, `channels` a pixel (RGB, or RGB and alpha), row-major, top
/// row first.
struct PixelBuffer {
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<float> pixels;

    PixelBuffer() = default;
    PixelBuffer(int width, int height, int channels = 3);
    /// Copies a finished tile into its place.
    void place(const TileResult& tile);
};

} // namespace crt::tracer
