// The render loop: the pixels of tiles over threads, or passes of paths over the image.
#include "tracer/renderer.hpp"

#include "tracer/pass_render.hpp"
#include "tracer/pixel_sampler.hpp"
#include "tracer/worker_threads.hpp"
#include "tracer/scene_images.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <mutex>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#include <sys/resource.h>
#endif

namespace crt::tracer {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The scene's settings with the job's sample budget applied.
scene::SettingsDesc withBudget(scene::SettingsDesc settings, const SampleBudget& budget) {
    if (budget.grid > 0) {
        settings.antialias = scene::Antialias::Grid;
        settings.supersampling = budget.grid;
        settings.samples = budget.grid * budget.grid;
    }
    return settings;
}

/// Everything built from a scene description before its first ray.
struct PreparedScene {
    std::unique_ptr<RenderScene> geometry;
    SceneImages images;
    std::unique_ptr<Background> background;
    std::optional<Fog> fog;
    std::vector<Light> lights;
    std::vector<Texture> textures;
    std::unique_ptr<Integrator> integrator;
    std::unique_ptr<PathIntegrator> path; ///< when the scene chose it
    std::unique_ptr<Camera> camera;
};

bool prepare(const scene::SceneDesc& desc, unsigned threads, PreparedScene& out, std::string& error) {
    const scene::SettingsDesc& s = desc.settings;
    out.geometry = buildRenderScene(desc, error, threads);
    if (!out.geometry) return false;
    if (!loadSceneImages(desc, out.images, error)) return false;
    for (const scene::LightDesc& l : desc.lights) out.lights.emplace_back(l, s.shadowSamples);
    for (const scene::TextureDesc& t : desc.textures)
        out.textures.emplace_back(t, out.images.find(scene::fileToOpen(t.resolvedFile, t.file)));
    out.background = std::make_unique<Background>(
        desc.background,
        out.images.find(scene::fileToOpen(desc.background.resolvedImage, desc.background.image)));
    if (desc.fog) out.fog.emplace(*desc.fog);
    const Fog* fog = out.fog ? &*out.fog : nullptr;
    out.integrator = std::make_unique<Integrator>(*out.geometry, s, out.lights, *out.background, fog, out.textures);
    if (s.integrator == scene::Integrator::Path)
        out.path =
            std::make_unique<PathIntegrator>(*out.geometry, s, out.lights, *out.background, fog, out.textures);
    out.camera = std::make_unique<Camera>(desc.camera, s.width, s.height, s.dofSamples);
    return true;
}

/// Traces one tile of the job into `pixels` (row-major, RenderJob::channels() floats a pixel).
void traceTile(const PixelSampler& sampler, const Tile& tile, const RenderJob& job, std::vector<float>& pixels,
               TraceContext& context) {
    const int channels = job.channels(), colorChannels = job.colorChannels();
    pixels.resize(static_cast<size_t>(tile.width()) * tile.height() * channels);
    float* out = pixels.data();
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x, out += channels)
            sampler.pixel(x, y, colorChannels, job.aovs, out, context);
}

/// Traces the tiles the job hands out (all of `tiles`, or what its nextTile says) on one thread
/// a `stats` entry, each tile once. Returns the tiles traced.
int traceEachTileOnce(const PixelSampler& sampler, const std::vector<Tile>& tiles, const RenderJob& job,
                      std::vector<RayStats>& stats) {
    const int channels = job.channels();
    const int tileCount = static_cast<int>(tiles.size());
    std::atomic<int> nextTile{0}, doneTiles{0};
    std::mutex callbackMutex; // the caller's callback sees one tile at a time
    auto worker = [&](size_t index) {
        TraceContext context;
        std::vector<float> pixels;
        while (!job.cancelled()) {
            const int tile = job.nextTile ? job.nextTile() : nextTile.fetch_add(1);
            if (tile < 0 || tile >= tileCount) break;
            traceTile(sampler, tiles[static_cast<size_t>(tile)], job, pixels, context);
            if (job.onTileDone) {
                std::lock_guard lock(callbackMutex);
                job.onTileDone(TileResult{tiles[static_cast<size_t>(tile)], tile, channels, pixels});
            }
            doneTiles.fetch_add(1);
        }
        stats[index] = context.stats;
    };
    runOnThreads(stats.size(), worker);
    return doneTiles.load();
}

/// The warnings of the scene's isosurfaces (its prototypes' too), each once however often it
/// is drawn.
void isosurfaceWarnings(const scene::SceneDesc& desc, const RenderScene& scene,
                        std::vector<const scene::IsosurfaceDesc*>& seen, std::string& warnings) {
    for (const Primitive& p : scene.primitives) {
        auto* iso = shapeIf<IsosurfaceGeometry>(p.geometry);
        if (!iso || std::find(seen.begin(), seen.end(), &iso->desc()) != seen.end()) continue;
        seen.push_back(&iso->desc());
        warnings += iso->warnings(scene::spanLocation(desc, iso->desc().source));
    }
    for (const auto& prototype : scene.prototypes) isosurfaceWarnings(desc, *prototype, seen, warnings);
}

/// The most memory this process has held resident so far.
uint64_t peakResidentBytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return static_cast<uint64_t>(usage.ru_maxrss) * 1024; // Linux counts kilobytes
}

/// Whether every tile is a non-empty rectangle inside the image; else says which is not.
bool tilesFit(const std::vector<Tile>& tiles, int width, int height, std::string& error) {
    for (const Tile& t : tiles) {
        if (t.x0 < 0 || t.y0 < 0 || t.x1 > width || t.y1 > height || t.width() <= 0 || t.height() <= 0) {
            error = fmt::format("tile [{}, {}) x [{}, {}) is not inside the {}x{} image", t.x0, t.x1,
                                t.y0, t.y1, width, height);
            return false;
        }
    }
    return true;
}

} // namespace

std::vector<Tile> regionTiles(const Tile& region, int size) {
    std::vector<Tile> tiles;
    for (int y = region.y0; y < region.y1; y += size)
        for (int x = region.x0; x < region.x1; x += size)
            tiles.push_back({x, y, std::min(x + size, region.x1), std::min(y + size, region.y1)});
    return tiles;
}

std::vector<Tile> imageTiles(int width, int height, int size) { return regionTiles({0, 0, width, height}, size); }

unsigned availableCores() {
#if defined(__linux__)
    // A mask larger than cpu_set_t (over 1,024 processors) fails: every core then.
    cpu_set_t allowed;
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

PixelBuffer::PixelBuffer(int width, int height, int channels)
    : width(width), height(height), channels(channels),
      pixels(static_cast<size_t>(width) * height * channels, 0.0f) {}

void PixelBuffer::place(const TileResult& result) {
    const Tile& t = result.tile;
    const size_t rowValues = static_cast<size_t>(t.width()) * channels;
    for (int y = t.y0; y < t.y1; ++y) {
        std::copy_n(result.pixels.data() + static_cast<size_t>(y - t.y0) * rowValues, rowValues,
                    pixels.data() + (static_cast<size_t>(y) * width + t.x0) * channels);
    }
}

RenderOutcome render(const scene::SceneDesc& desc, const RenderJob& job) {
    RenderOutcome outcome;
    if (!tilesFit(job.tiles, desc.settings.width, desc.settings.height, outcome.error)) return outcome;
    auto buildStart = std::chrono::steady_clock::now();
    const unsigned jobThreads = job.threads > 0 ? static_cast<unsigned>(job.threads) : availableCores();
    PreparedScene prepared;
    if (!prepare(desc, jobThreads, prepared, outcome.error)) return outcome;
    const scene::SettingsDesc settings = withBudget(desc.settings, job.samples);
    PixelSampler sampler(*prepared.integrator, prepared.path.get(), desc.camera.aperture > 0, *prepared.camera, settings,
                         desc.motion, job.alpha);
    outcome.buildSeconds = secondsSince(buildStart);
    outcome.primitives = prepared.geometry->storedPrimitives();
    outcome.drawnPrimitives = prepared.geometry->primitives.size() + prepared.geometry->instances.size();
    outcome.sceneBytes = prepared.geometry->byteSize();
    outcome.bvhNodes = prepared.geometry->bvh.nodeCount();
    outcome.bvhDepth = prepared.geometry->bvh.depth();
    outcome.shading = prepared.integrator->features().names();
    outcome.samples = prepared.path ? static_cast<uint64_t>(settings.samples)
                      : settings.antialias == scene::Antialias::Grid || settings.antialias == scene::Antialias::Stratified
                          ? static_cast<uint64_t>(settings.supersampling) * settings.supersampling
                          : 4;

    auto renderStart = std::chrono::steady_clock::now();
    const std::vector<Tile> tiles =
        job.tiles.empty() ? imageTiles(settings.width, settings.height) : job.tiles;
    const int tileCount = static_cast<int>(tiles.size());
    outcome.tileCount = tileCount;
    const unsigned threadCount = std::max(1u, std::min<unsigned>(jobThreads, static_cast<unsigned>(tileCount)));
    std::vector<RayStats> stats(threadCount);
    if (!job.aovs.empty() && !prepared.path) {
        outcome.error = "AOVs are written by the path integrator only";
        return outcome;
    }
    if (job.progressive && prepared.path) {
        if (job.nextTile) {
            outcome.error = "a progressive render traces every tile itself; it cannot share them";
            return outcome;
        }
        outcome.tilesDone = renderInPasses(sampler, tiles, job, settings.width, settings.height, stats);
    } else {
        outcome.tilesDone = traceEachTileOnce(sampler, tiles, job, stats);
    }
    for (const RayStats& st : stats) outcome.stats += st;
    outcome.renderSeconds = secondsSince(renderStart);
    // A job that hands out its own tiles may trace only some of them: only its cancel says
    // whether it was stopped.
    outcome.cancelled = job.nextTile ? job.cancelled()
                                     : outcome.tilesDone < tileCount;
    outcome.ok = !outcome.cancelled;
    std::vector<const scene::IsosurfaceDesc*> seen;
    isosurfaceWarnings(desc, *prepared.geometry, seen, outcome.warnings);
    outcome.peakBytes = peakResidentBytes();
    return outcome;
}

} // namespace crt::tracer
