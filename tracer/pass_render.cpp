#include "tracer/pass_render.hpp"

#include "tracer/worker_threads.hpp"

#include <atomic>

namespace crt::tracer {

namespace {

/// The paths a pixel has after pass `pass` (from 0): a picture at once, then passes short
/// enough that a deadline stops the render close to it.
int pathsAfterPass(int pass) { return pass < 5 ? 1 << pass : 16 * (pass - 3); }

/// Every tile's pixels' running sums, row by row, one block a tile.
class PassState {
public:
    PassState(const std::vector<Tile>& tiles, AovSet aovs) : aovs_(aovs), offsets_(tiles.size() + 1, 0) {
        for (size_t t = 0; t < tiles.size(); ++t)
            offsets_[t + 1] = offsets_[t] + static_cast<size_t>(tiles[t].width()) * tiles[t].height();
        pixels_.resize(offsets_.back());
        if (!aovs.empty()) sums_.resize(offsets_.back());
    }

    PathPixel* tile(size_t t) { return pixels_.data() + offsets_[t]; }
    /// What tile `t`'s pixels' AOVs need, or null when none is asked for.
    PathAovSums* sums(size_t t) { return sums_.empty() ? nullptr : sums_.data() + offsets_[t]; }
    const std::vector<PathPixel>& pixels() const { return pixels_; }

    /// Tile `t`'s pixels as writePathPixel writes them, with the AOVs or without.
    void write(size_t t, int colorChannels, bool withAovs, std::vector<float>& out) const {
        const AovSet aovs = withAovs ? aovs_ : AovSet{};
        const size_t channels = static_cast<size_t>(colorChannels + aovs.channels());
        out.resize((offsets_[t + 1] - offsets_[t]) * channels);
        const PathAovSums none;
        for (size_t i = offsets_[t], k = 0; i < offsets_[t + 1]; ++i, k += channels)
            writePathPixel(pixels_[i], aovs.empty() ? none : sums_[i], colorChannels, aovs, out.data() + k);
    }

private:
    AovSet aovs_;
    std::vector<size_t> offsets_;
    std::vector<PathPixel> pixels_;
    std::vector<PathAovSums> sums_;
};

bool pastDeadline(const RenderJob& job) {
    return job.progressive->deadline && std::chrono::steady_clock::now() >= *job.progressive->deadline;
}

/// One pass: each thread takes tiles in turn and adds paths to their pixels, up to `upTo`.
/// Returns the tiles it went through; `unsettled`, whether a pixel wants more.
int tracePass(const PixelSampler& sampler, const std::vector<Tile>& tiles, const RenderJob& job, int upTo,
               bool mayStop, PassState& state, std::vector<RayStats>& stats, bool& unsettled) {
    std::atomic<int> next{0}, traced{0};
    std::atomic<bool> wanting{false};
    const int tileCount = static_cast<int>(tiles.size());
    auto worker = [&](size_t index) {
        TraceContext context;
        context.stats = stats[index];
        for (;;) {
            if (job.cancelled() || (mayStop && pastDeadline(job))) break;
            const int t = next.fetch_add(1);
            if (t >= tileCount) break;
            const Tile& tile = tiles[static_cast<size_t>(t)];
            PathPixel* pixel = state.tile(static_cast<size_t>(t));
            PathAovSums* sums = state.sums(static_cast<size_t>(t));
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x, ++pixel) {
                    sampler.addPaths(x, y, *pixel, upTo, context, sums ? sums++ : nullptr);
                    if (!pixel->settled) wanting.store(true, std::memory_order_relaxed);
                }
            traced.fetch_add(1);
        }
        stats[index] = context.stats;
    };
    runOnThreads(stats.size(), worker);
    unsettled = wanting.load();
    return traced.load();
}

/// The image so far, for the job's onPass.
void reportPass(const std::vector<Tile>& tiles, const RenderJob& job, int pass, const PassState& state,
                PixelBuffer& image) {
    std::vector<float> means;
    for (size_t t = 0; t < tiles.size(); ++t) {
        state.write(t, image.channels, false, means);
        image.place(TileResult{tiles[t], static_cast<int>(t), image.channels, means});
    }
    RayStats paths;
    double pathCount = 0;
    for (const PathPixel& p : state.pixels()) {
        paths.addPathPixel(static_cast<uint64_t>(p.paths), p.relativeError());
        pathCount += p.paths;
    }
    const double meanPaths = paths.pathPixels > 0 ? pathCount / static_cast<double>(paths.pathPixels) : 0;
    job.progressive->onPass(PassImage{pass + 1, meanPaths, paths.imageRelativeError(), &image});
}

} // namespace

int renderInPasses(const PixelSampler& sampler, const std::vector<Tile>& tiles, const RenderJob& job, int width,
                   int height, std::vector<RayStats>& stats) {
    PassState state(tiles, job.aovs);
    PixelBuffer image;
    if (job.progressive->onPass) image = PixelBuffer(width, height, job.colorChannels());
    for (int pass = 0;; ++pass) {
        bool unsettled = false;
        const int traced = tracePass(sampler, tiles, job, pathsAfterPass(pass), pass > 0, state, stats, unsettled);
        if (job.cancelled()) return 0;
        if (traced == 0) break; // stopped before the pass began: the image is the last one shown
        if (job.progressive->onPass) reportPass(tiles, job, pass, state, image);
        if (traced < static_cast<int>(tiles.size()) || !unsettled) break;
    }
    for (const PathPixel& p : state.pixels())
        stats[0].addPathPixel(static_cast<uint64_t>(p.paths), p.relativeError());
    std::vector<float> pixels;
    for (size_t t = 0; t < tiles.size(); ++t) {
        state.write(t, job.colorChannels(), true, pixels);
        if (job.onTileDone) job.onTileDone(TileResult{tiles[t], static_cast<int>(t), job.channels(), pixels});
    }
    return static_cast<int>(tiles.size());
}

} // namespace crt::tracer
