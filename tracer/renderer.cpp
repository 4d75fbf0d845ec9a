// The render loop: per-pixel sampling (grid, stratified, adaptive, depth of field) over tiles
// and threads.
#include "tracer/renderer.hpp"

#include "tracer/camera.hpp"
#include "tracer/integrator.hpp"
#include "tracer/path_integrator.hpp"
#include "tracer/scene_images.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
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

/// Computes pixels; one per thread, sharing the read-only scene.
class PixelSampler {
public:
    /// RGB and alpha: samples are averaged in all four, so edges against a transparent
    /// background get partial alpha.
    using Color = glm::dvec4;

    /// `path`: the path integrator, when the scene chose it; `lens`: whether its paths start
    /// on the lens (an aperture).
    PixelSampler(const Integrator& integrator, const PathIntegrator* path, bool lens, const Camera& camera,
                 const scene::SettingsDesc& settings, bool transparentBackground)
        : integrator_(integrator), path_(path), pathLens_(lens), camera_(camera), settings_(settings),
          dofSamples_(camera.usesLens() ? std::max(settings.dofSamples, 1) : 1),
          bounces_(settings.bounceLimit()), transparentBackground_(transparentBackground) {}

    /// The pixel's color and alpha (coverage; the color is premultiplied by it).
    Color pixel(int x, int y, TraceContext& context) const {
        uint64_t pixelIndex = static_cast<uint64_t>(y) * settings_.width + x;
        if (path_) return pathPixel(x, y, pixelIndex, context);
        bool adaptive = settings_.antialias == scene::Antialias::Adaptive ||
                        settings_.antialias == scene::Antialias::ShowAdaptive;
        if (adaptive) {
            bool subdivides = false;
            uint32_t sampleIndex = 0;
            Color c = region(x + 0.5, y + 0.5, 1.0, 0, pixelIndex, sampleIndex, subdivides, context);
            if (settings_.antialias == scene::Antialias::ShowAdaptive && subdivides) return {1, 0, 0, 1};
            return c;
        }
        int n = std::max(settings_.supersampling, 1);
        bool jittered = settings_.antialias == scene::Antialias::Stratified;
        Color sum(0.0);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                uint32_t k = static_cast<uint32_t>(j * n + i);
                Vec2 offset = jittered ? cellJitter(pixelIndex, k) : Vec2(0.5);
                sum += sample(x + (i + offset.x) / n, y + (j + offset.y) / n, pixelIndex, k, context);
            }
        return sum / static_cast<double>(n * n);
    }

private:
    /// The mean of `samples` paths, each through its own point of the pixel (and of the lens);
    /// with a target error, of as many as the pixel needs for it (checked every
    /// kMinAdaptiveSamples paths, so the count does not hang on the noise of a single one).
    Color pathPixel(int x, int y, uint64_t pixelIndex, TraceContext& context) const {
        constexpr int kBatch = scene::SettingsDesc::kMinAdaptiveSamples;
        Color sum(0.0);
        double sumLuminance = 0, sumSquares = 0;
        int k = 0;
        while (k < settings_.samples) {
            context.rng = SampleRng(settings_.seed, pixelIndex, static_cast<uint64_t>(k));
            const Vec2 offset = context.rng.uniform2();
            const Ray ray = pathLens_ ? camera_.lensRay(x + offset.x, y + offset.y, context.rng.uniform2())
                                      : camera_.ray(x + offset.x, y + offset.y);
            ++context.stats.cameraRays;
            const Color c = path_->traceCamera(ray, transparentBackground_, context);
            sum += c;
            const double l = luminance(Vec3(c));
            sumLuminance += l, sumSquares += l * l;
            ++k;
            if (settings_.targetError > 0 && k % kBatch == 0 &&
                relativeError(sumLuminance, sumSquares, k) <= settings_.targetError)
                break;
        }
        context.stats.addPathPixel(static_cast<uint64_t>(k), relativeError(sumLuminance, sumSquares, k));
        return sum / static_cast<double>(k);
    }

    /// The standard error of the mean of n values (by their sum and sum of squares) relative
    /// to the mean, or to 1/1000 where it is darker, so that black pixels stop; 1 for one value.
    static double relativeError(double sum, double sumSquares, int n) {
        if (n < 2) return 1;
        const double mean = sum / n;
        const double variance = std::max(0.0, sumSquares / n - mean * mean) * n / (n - 1);
        return std::sqrt(variance / n) / std::max(mean, 1e-3);
    }

    /// Where stratified sample `k` lies in its grid cell, in [0, 1)². Its own stream of the
    /// pixel's random numbers, apart from the stream the sample then traces with, so the
    /// position is not correlated with the sample's light and lens choices.
    Vec2 cellJitter(uint64_t pixelIndex, uint32_t k) const {
        constexpr uint64_t kJitterStream = uint64_t{1} << 40;
        return SampleRng(settings_.seed, pixelIndex, kJitterStream + k).uniform2();
    }

    /// Spec §6 "adaptive": the four quadrant centres, a quadrant subdivided while its
    /// samples disagree by more than the threshold, up to aadepth levels; area-weighted mean.
    Color region(double cx, double cy, double size, int level, uint64_t pixelIndex, uint32_t& sampleIndex,
                 bool& subdivides, TraceContext& context) const {
        Color corners[4];
        double q = size / 4;
        const double offsets[4][2] = {{-q, -q}, {q, -q}, {-q, q}, {q, q}};
        for (int k = 0; k < 4; ++k)
            corners[k] = sample(cx + offsets[k][0], cy + offsets[k][1], pixelIndex, sampleIndex++, context);
        double spread = 0;
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                {
                    Color d = glm::abs(corners[a] - corners[b]);
                    spread = std::max({spread, d.x, d.y, d.z, d.w});
                }
        if (spread > settings_.aaThreshold && level < settings_.aaDepth) {
            subdivides = true;
            if (settings_.antialias == scene::Antialias::ShowAdaptive) return corners[0];
            for (int k = 0; k < 4; ++k)
                corners[k] = region(cx + offsets[k][0], cy + offsets[k][1], size / 2, level + 1, pixelIndex,
                                    sampleIndex, subdivides, context);
        }
        return (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
    }

    Color sample(double u, double v, uint64_t pixelIndex, uint32_t sampleIndex, TraceContext& context) const {
        context.rng = SampleRng(settings_.seed, pixelIndex, sampleIndex);
        if (dofSamples_ <= 1) {
            ++context.stats.cameraRays;
            return integrator_.traceCamera(camera_.ray(u, v), bounces_, transparentBackground_, context);
        }
        // Depth of field: a low-discrepancy set of lens points, shifted per pixel sample.
        Vec2 shift = context.rng.uniform2();
        Color sum(0.0);
        for (int k = 0; k < dofSamples_; ++k) {
            Vec2 lens = hammersley(static_cast<uint32_t>(k), static_cast<uint32_t>(dofSamples_), shift);
            ++context.stats.cameraRays;
            sum += integrator_.traceCamera(camera_.lensRay(u, v, lens), bounces_,
                                           transparentBackground_, context);
        }
        return sum / static_cast<double>(dofSamples_);
    }

    const Integrator& integrator_;
    const PathIntegrator* path_;
    bool pathLens_;
    const Camera& camera_;
    const scene::SettingsDesc& settings_;
    int dofSamples_;
    int bounces_; ///< reflections and refractions a camera ray's path may take in all
    bool transparentBackground_;
};

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
    out.integrator = std::make_unique<Integrator>(*out.geometry, s, out.lights, *out.background, out.textures);
    if (s.integrator == scene::Integrator::Path)
        out.path = std::make_unique<PathIntegrator>(*out.geometry, s, out.lights, *out.background, out.textures);
    out.camera = std::make_unique<Camera>(desc.camera, s.width, s.height, s.dofSamples);
    return true;
}

/// Traces one tile into `pixels` (row-major, `channels` floats a pixel: RGB, then alpha).
void traceTile(const PixelSampler& sampler, const Tile& tile, int channels, std::vector<float>& pixels,
               TraceContext& context) {
    pixels.resize(static_cast<size_t>(tile.width()) * tile.height() * channels);
    float* out = pixels.data();
    for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x, out += channels) {
            glm::dvec4 c = sampler.pixel(x, y, context);
            for (int i = 0; i < channels; ++i) out[i] = static_cast<float>(c[i]);
        }
    }
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
                         job.alpha);
    const int channels = job.alpha ? 4 : 3;
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
    std::atomic<int> nextTile{0}, doneTiles{0};
    const unsigned threadCount = std::max(1u, std::min<unsigned>(jobThreads, static_cast<unsigned>(tileCount)));
    std::vector<RayStats> stats(threadCount);
    std::mutex callbackMutex; // the caller's callback sees one tile at a time

    auto worker = [&](unsigned index) {
        TraceContext context;
        std::vector<float> pixels;
        while (!(job.cancel && job.cancel->load(std::memory_order_relaxed))) {
            const int tile = job.nextTile ? job.nextTile() : nextTile.fetch_add(1);
            if (tile < 0 || tile >= tileCount) break;
            traceTile(sampler, tiles[static_cast<size_t>(tile)], channels, pixels, context);
            if (job.onTileDone) {
                std::lock_guard lock(callbackMutex);
                job.onTileDone(TileResult{tiles[static_cast<size_t>(tile)], tile, channels, pixels});
            }
            doneTiles.fetch_add(1);
        }
        stats[index] = context.stats;
    };
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < threadCount; ++i) threads.emplace_back(worker, i);
    worker(0);
    for (std::thread& t : threads) t.join();

    for (const RayStats& st : stats) outcome.stats += st;
    outcome.renderSeconds = secondsSince(renderStart);
    outcome.tilesDone = doneTiles.load();
    // A job that hands out its own tiles may trace only some of them: only its cancel says
    // whether it was stopped.
    outcome.cancelled = job.nextTile ? job.cancel && job.cancel->load()
                                     : outcome.tilesDone < tileCount;
    outcome.ok = !outcome.cancelled;
    std::vector<const scene::IsosurfaceDesc*> seen;
    isosurfaceWarnings(desc, *prepared.geometry, seen, outcome.warnings);
    outcome.peakBytes = peakResidentBytes();
    return outcome;
}

} // namespace crt::tracer
