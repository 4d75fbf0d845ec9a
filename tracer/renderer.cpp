// The render loop: per-pixel sampling (grid, adaptive, depth of field) over tiles and threads.
#include "tracer/renderer.hpp"

#include "tracer/camera.hpp"
#include "tracer/integrator.hpp"
#include "tracer/scene_images.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <latch>
#include <memory>
#include <mutex>
#include <thread>

namespace crt::tracer {

namespace {

constexpr int kTileSize = 16;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Computes pixels; one per thread, sharing the read-only scene.
class PixelSampler {
public:
    PixelSampler(const Integrator& integrator, const Camera& camera, const SettingsDesc& settings)
        : integrator_(integrator), camera_(camera), settings_(settings),
          dofSamples_(camera.usesLens() ? std::max(settings.dofSamples, 1) : 1) {}

    Vec3 pixel(int x, int y, TraceContext& context) const {
        uint64_t pixelIndex = static_cast<uint64_t>(y) * settings_.width + x;
        if (settings_.antialias != Antialias::Grid) {
            bool subdivides = false;
            uint32_t sampleIndex = 0;
            Vec3 c = region(x + 0.5, y + 0.5, 1.0, 0, pixelIndex, sampleIndex, subdivides, context);
            if (settings_.antialias == Antialias::ShowAdaptive && subdivides) return {1, 0, 0};
            return c;
        }
        int n = std::max(settings_.supersampling, 1);
        Vec3 sum(0.0);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                sum += sample(x + (i + 0.5) / n, y + (j + 0.5) / n, pixelIndex, static_cast<uint32_t>(j * n + i), context);
        return sum / static_cast<double>(n * n);
    }

private:
    /// Spec §6 "adaptive": the four quadrant centres, a quadrant subdivided while its
    /// samples disagree by more than the threshold, up to aadepth levels; area-weighted mean.
    Vec3 region(double cx, double cy, double size, int level, uint64_t pixelIndex, uint32_t& sampleIndex,
                bool& subdivides, TraceContext& context) const {
        Vec3 corners[4];
        double q = size / 4;
        const double offsets[4][2] = {{-q, -q}, {q, -q}, {-q, q}, {q, q}};
        for (int k = 0; k < 4; ++k)
            corners[k] = sample(cx + offsets[k][0], cy + offsets[k][1], pixelIndex, sampleIndex++, context);
        double spread = 0;
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                {
                    Vec3 d = absolute(corners[a] - corners[b]);
                    spread = std::max({spread, d.x, d.y, d.z});
                }
        if (spread > settings_.aaThreshold && level < settings_.aaDepth) {
            subdivides = true;
            if (settings_.antialias == Antialias::ShowAdaptive) return corners[0];
            for (int k = 0; k < 4; ++k)
                corners[k] = region(cx + offsets[k][0], cy + offsets[k][1], size / 2, level + 1, pixelIndex,
                                    sampleIndex, subdivides, context);
        }
        return (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
    }

    Vec3 sample(double u, double v, uint64_t pixelIndex, uint32_t sampleIndex, TraceContext& context) const {
        context.rng = SampleRng(settings_.seed, pixelIndex, sampleIndex);
        if (dofSamples_ <= 1) {
            ++context.stats.cameraRays;
            return integrator_.trace(camera_.ray(u, v), settings_.recursionDepth, 0, -1, context);
        }
        // Depth of field: a low-discrepancy set of lens points, shifted per pixel sample.
        Vec2 shift = context.rng.uniform2();
        Vec3 sum(0.0);
        for (int k = 0; k < dofSamples_; ++k) {
            Vec2 lens = hammersley(static_cast<uint32_t>(k), static_cast<uint32_t>(dofSamples_), shift);
            ++context.stats.cameraRays;
            sum += integrator_.trace(camera_.lensRay(u, v, lens), settings_.recursionDepth, 0, -1, context);
        }
        return sum / static_cast<double>(dofSamples_);
    }

    const Integrator& integrator_;
    const Camera& camera_;
    const SettingsDesc& settings_;
    int dofSamples_;
};

/// Where the workers put pixels, and the reports of bands of rows as they become final: a
/// tile row is final when all its tiles are, and bands go out in order, so a finished row
/// waits for the rows above it. Unless the whole frame is kept, each tile row has a buffer
/// of its own, taken when its first tile starts and given back once the row is reported:
/// a render streamed to its file then holds the rows in flight, not the whole image (a
/// 1920×1080 frame of floats is 25 MB, and first touches of fresh memory cost as much as
/// the trace of a simple scene).
class FrameRows {
public:
    using Report = std::function<void(int yBegin, int yEnd, std::span<const float> rgb)>;

    FrameRows(PixelBuffer& frame, bool keepFrame, int tilesX, int tilesY, const Report& report)
        : frame_(frame), keep_(keepFrame || !report), report_(report),
          rowValues_(static_cast<size_t>(frame.width) * 3), tilesLeft_(static_cast<size_t>(tilesY), tilesX),
          rowBuffers_(keep_ ? 0 : static_cast<size_t>(tilesY)) {}

    /// Allocates the kept frame; a separate step so that the caller decides when its pages
    /// are first touched.
    void allocate() {
        if (keep_) frame_.rgb.assign(rowValues_ * static_cast<size_t>(frame_.height), 0.0f);
    }

    /// The first value of the first image row of tile row `tileRow`, for a tile being traced;
    /// the rows below follow every rowValues() floats.
    float* firstRowOf(int tileRow) {
        if (keep_) return frame_.rgb.data() + static_cast<size_t>(tileRow) * kTileSize * rowValues_;
        std::lock_guard<std::mutex> lock(mutex_);
        std::unique_ptr<float[]>& buffer = rowBuffers_[static_cast<size_t>(tileRow)];
        // Left uninitialised: the row's tiles write every value before it is reported.
        if (!buffer) buffer.reset(new float[rowValues_ * kTileSize]);
        return buffer.get();
    }

    size_t rowValues() const { return rowValues_; }

    void tileDone(int tileRow) {
        if (!report_) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (--tilesLeft_[static_cast<size_t>(tileRow)] > 0) return;
        while (nextRow_ < static_cast<int>(tilesLeft_.size()) && tilesLeft_[static_cast<size_t>(nextRow_)] == 0) {
            const int yBegin = nextRow_ * kTileSize, yEnd = std::min(yBegin + kTileSize, frame_.height);
            const size_t values = static_cast<size_t>(yEnd - yBegin) * rowValues_;
            if (keep_) {
                report_(yBegin, yEnd, std::span<const float>(frame_.rgb.data() + yBegin * rowValues_, values));
            } else {
                std::unique_ptr<float[]>& buffer = rowBuffers_[static_cast<size_t>(nextRow_)];
                report_(yBegin, yEnd, std::span<const float>(buffer.get(), values));
                buffer.reset();
            }
            ++nextRow_;
        }
    }

private:
    PixelBuffer& frame_;
    const bool keep_;
    const Report& report_;
    const size_t rowValues_; ///< floats per image row (width × 3)
    std::mutex mutex_;
    std::vector<int> tilesLeft_; ///< per tile row
    int nextRow_ = 0;            ///< the first tile row not reported
    std::vector<std::unique_ptr<float[]>> rowBuffers_; ///< per tile row, when the frame is not kept
};

} // namespace

RenderOutcome renderScene(const SceneDesc& desc, const RenderSettings& settings) {
    RenderOutcome outcome;
    auto buildStart = std::chrono::steady_clock::now();
    const SettingsDesc& s = desc.settings;
    std::unique_ptr<RenderScene> scene = buildRenderScene(desc, outcome.error);
    if (!scene) return outcome;
    SceneImages images;
    if (!loadSceneImages(desc, images, outcome.error)) return outcome;
    std::vector<Light> lights;
    for (const LightDesc& l : desc.lights) lights.emplace_back(l, s.shadowSamples);
    std::vector<Texture> textures;
    for (const TextureDesc& t : desc.textures)
        textures.emplace_back(t, images.find(fileToOpen(t.resolvedFile, t.file)));
    Background background(desc.background,
                          images.find(fileToOpen(desc.background.resolvedImage, desc.background.image)));
    Integrator integrator(*scene, s, std::move(lights), background, std::move(textures));
    Camera camera(desc.camera, s.width, s.height, s.dofSamples);
    PixelSampler sampler(integrator, camera, s);
    outcome.buildSeconds = secondsSince(buildStart);
    outcome.primitives = scene->primitives.size();
    outcome.bvhNodes = scene->bvh.nodeCount();
    outcome.bvhDepth = scene->bvh.depth();
    outcome.samples = s.antialias == Antialias::Grid ? static_cast<uint64_t>(s.supersampling) * s.supersampling : 4;

    auto renderStart = std::chrono::steady_clock::now();
    PixelBuffer& frame = outcome.frame;
    frame.width = s.width;
    frame.height = s.height;
    int tilesX = (s.width + kTileSize - 1) / kTileSize, tilesY = (s.height + kTileSize - 1) / kTileSize;
    int tileCount = tilesX * tilesY;
    std::atomic<int> nextTile{0}, doneTiles{0};
    unsigned threadCount = settings.threads > 0 ? static_cast<unsigned>(settings.threads)
                                                : std::max(1u, std::thread::hardware_concurrency());
    threadCount = std::min<unsigned>(threadCount, static_cast<unsigned>(tileCount));
    std::vector<RayStats> stats(threadCount);
    FrameRows rows(frame, settings.keepFrame, tilesX, tilesY, settings.onRowsDone);

    std::latch ready(1); // the threads are started and the frame is allocated
    auto worker = [&](unsigned index) {
        if (index > 0) ready.wait();
        if (index + 1 == threadCount && index > 0 && settings.beforeLastWorker) settings.beforeLastWorker();
        TraceContext context;
        while (true) {
            if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) break;
            int tile = nextTile.fetch_add(1);
            if (tile >= tileCount) break;
            const int tileRow = tile / tilesX;
            int x0 = (tile % tilesX) * kTileSize, y0 = tileRow * kTileSize;
            float* tileStart = rows.firstRowOf(tileRow) + 3 * static_cast<size_t>(x0);
            for (int y = y0; y < std::min(y0 + kTileSize, s.height); ++y) {
                float* out = tileStart + static_cast<size_t>(y - y0) * rows.rowValues();
                for (int x = x0; x < std::min(x0 + kTileSize, s.width); ++x, out += 3) {
                    Vec3 c = sampler.pixel(x, y, context);
                    out[0] = static_cast<float>(c.r);
                    out[1] = static_cast<float>(c.g);
                    out[2] = static_cast<float>(c.b);
                }
            }
            doneTiles.fetch_add(1);
            rows.tileDone(tileRow);
        }
        stats[index] = context.stats;
    };
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < threadCount; ++i) threads.emplace_back(worker, i);
    // Report from a helper so the caller's callback runs while the workers trace. It waits
    // on a condition the end of the render signals, so the render never waits out a period.
    std::mutex reportMutex;
    std::condition_variable reportWake;
    bool finished = false;
    std::thread reporter;
    if (settings.onProgress) {
        reporter = std::thread([&] {
            std::unique_lock lock(reportMutex);
            while (!finished) {
                settings.onProgress(doneTiles.load(), tileCount);
                reportWake.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
            }
        });
    }
    if (settings.onThreadsStarted) settings.onThreadsStarted();
    // Zeroing a kept frame (25 MB at 1920×1080) faults in every page: done after the threads
    // start, it overlaps whatever onThreadsStarted began (crtc's image module load).
    rows.allocate();
    ready.count_down();
    worker(0);
    for (std::thread& t : threads) t.join();
    if (reporter.joinable()) {
        {
            std::lock_guard lock(reportMutex);
            finished = true;
        }
        reportWake.notify_one();
        reporter.join();
        settings.onProgress(doneTiles.load(), tileCount);
    }
    for (const RayStats& st : stats) outcome.stats += st;
    outcome.renderSeconds = secondsSince(renderStart);
    outcome.cancelled = settings.cancel && settings.cancel->load() && doneTiles.load() < tileCount;
    outcome.ok = !outcome.cancelled;
    return outcome;
}

} // namespace crt::tracer
