// Rendering from crtc: frames, output naming, progress, Ctrl-C, the summary line and --stats.
#include "render_command.hpp"

#include "progress_reporter.hpp"
#include "row_assembler.hpp"
#include "scene/quality_overrides.hpp"
#include "scene/scene_json.hpp"
#include "streamed_output.hpp"
#include "tracer/image_io/image_io.hpp"
#include "tracer/renderer.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>

namespace crt::crtc {

namespace fs = std::filesystem;
namespace image_io = tracer::image_io;
using lang::Compilation;

namespace {

std::atomic<bool> interrupted{false};
/// Set by Ctrl-C or by an output that failed: either way the rest of the render is of no use.
std::atomic<bool> stopRendering{false};

extern "C" void onInterrupt(int) {
    interrupted.store(true);
    stopRendering.store(true);
}

const std::regex& framePattern() {
    static const std::regex pattern("%0?[0-9]*d");
    return pattern;
}

/// Where the frames of a render go.
struct OutputPlan {
    std::string path;
    bool numbered = false; ///< a file per frame, named by a pattern such as %04d
    bool gif = false;      ///< one animated GIF

    std::string target(int frame) const { return numbered ? numberedOutput(path, frame) : path; }
};

/// The sums over a render's frames, for the summary line and --stats.
struct RenderTotals {
    tracer::RenderOutcome outcome;
    uint64_t reusedFrames = 0;
    uint64_t pixels = 0; ///< pixels rendered, over all frames
    int width = 0, height = 0;

    void add(const tracer::RenderOutcome& r, uint64_t framePixels) {
        pixels += framePixels;
        outcome.stats += r.stats;
        outcome.buildSeconds += r.buildSeconds;
        outcome.renderSeconds += r.renderSeconds;
        outcome.primitives = r.primitives;
        outcome.bvhNodes = r.bvhNodes;
        outcome.bvhDepth = r.bvhDepth;
    }
};

void printStats(const RenderTotals& totals) {
    const tracer::RenderOutcome& r = totals.outcome;
    const tracer::RayStats& s = r.stats;
    std::cerr << fmt::format(
        "crtc: stats: primitives {}, BVH nodes {}, BVH depth {}\n"
        "crtc: stats: rays: camera {}, reflection {}, refraction {}, shadow {} (total {})\n"
        "crtc: stats: BVH nodes visited {}, intersection tests {}\n"
        "crtc: stats: build {:.3f}s, render {:.3f}s, frames reused unchanged {}\n",
        r.primitives, r.bvhNodes, r.bvhDepth, s.cameraRays, s.reflectionRays, s.refractionRays,
        s.shadowRays, s.totalRays(), s.nodesVisited, s.intersectionTests, r.buildSeconds,
        r.renderSeconds, totals.reusedFrames);
}

/// The camera rays a pixel got on average: depth of field and adaptive samples included.
std::string samplesPerPixel(const RenderTotals& totals) {
    if (totals.pixels == 0) return "no pixels rendered";
    const uint64_t rays = totals.outcome.stats.cameraRays;
    if (rays % totals.pixels == 0) {
        const uint64_t samples = rays / totals.pixels;
        return fmt::format("{} sample{}/pixel", samples, samples == 1 ? "" : "s");
    }
    return fmt::format("{:.2f} samples/pixel", static_cast<double>(rays) / totals.pixels);
}

void printSummary(const RenderTotals& totals, int frames, double seconds, const std::string& output) {
    const tracer::RenderOutcome& r = totals.outcome;
    const double mrays = r.renderSeconds > 0 ? r.stats.totalRays() / r.renderSeconds / 1e6 : 0;
    std::cerr << fmt::format("crtc: {}x{}, {}{}, {:.2f}s, {:.1f} Mrays/s -> {}\n", totals.width,
                             totals.height, samplesPerPixel(totals),
                             frames > 1 ? fmt::format(", {} frames", frames) : "", seconds, mrays,
                             output);
}

image_io::ImageBuffer toBuffer(tracer::PixelBuffer frame) {
    image_io::ImageBuffer b;
    b.width = frame.width;
    b.height = frame.height;
    b.channels = 3;
    b.pixels = std::move(frame.rgb);
    return b;
}

/// The scene without its time and frame number: two frames with the same key render alike.
std::string sceneKey(scene::SceneDesc scene) {
    scene.time = 0;
    scene.frame = 0;
    return scene::sceneToJson(scene);
}

/// Checks the output name against the frames rendered; false, having said why, for a name
/// crtc cannot write.
bool planOutput(const Options& options, OutputPlan& plan) {
    const FrameSelection& frames = options.frames;
    const bool sequence = frames.count > 1;
    plan.path = options.output.empty() ? defaultOutput(options.script, sequence && frames.selected() > 1)
                                       : options.output;
    const bool gifName = fs::path(plan.path).extension() == ".gif";
    plan.numbered = sequence && hasFramePattern(plan.path);
    // One frame of an animation is an image like any other, unless a GIF is asked for.
    plan.gif = sequence && !plan.numbered && (frames.selected() > 1 || gifName);
    if (plan.gif && !gifName) {
        std::cerr << "crtc: with --frames, -o must end in .gif or contain a frame number pattern "
                     "such as %04d\n";
        return false;
    }
    if (!image_io::isSupportedOutput(plan.target(frames.begin()))) {
        std::cerr << fmt::format("crtc: cannot write '{}': unknown image format (use .png, .jpg, "
                                 ".tif, .exr, .hdr or .gif)\n",
                                 plan.path);
        return false;
    }
    return true;
}

/// The part of `scene`'s image that is rendered: --region, or all of it. False, having said
/// why, for a region outside the image.
bool renderedRegion(const Options& options, const scene::SceneDesc& scene, tracer::Tile& region) {
    const int width = scene.settings.width, height = scene.settings.height;
    region = options.region.value_or(tracer::Tile{0, 0, width, height});
    if (region.x1 <= width && region.y1 <= height) return true;
    std::cerr << fmt::format("crtc: --region {}:{}:{}:{} is not inside the {}x{} image\n", region.x0, region.y0,
                             region.x1, region.y1, width, height);
    return false;
}

/// Renders `region` of one frame of `scene`: streamed to the file `target` as its rows are
/// finished, or, with `keep`, into `keep` only. Returns 0 or crtc's exit status.
int renderFrame(const Options& options, const scene::SceneDesc& scene, const tracer::Tile& region,
                const std::string& target, const image_io::WriteOptions& write, ProgressReporter& progress,
                tracer::PixelBuffer* keep, RenderTotals& totals) {
    const int width = region.width(), height = region.height();
    std::optional<StreamedOutput> streamed;
    std::optional<RowAssembler> rows;
    if (!keep) {
        streamed.emplace(target, width, height, write, stopRendering);
        rows.emplace(width, height, [&](int yBegin, int yEnd, std::span<const float> rgb) {
            streamed->addRows(yBegin, yEnd, rgb);
        });
    }
    tracer::RenderJob job;
    job.tiles = tracer::regionTiles(region);
    job.threads = options.threads;
    job.cancel = &stopRendering;
    int done = 0;
    job.onTileDone = [&](const tracer::TileResult& result) {
        // The output image is the region alone: its tiles move to its top left corner.
        const tracer::Tile& t = result.tile;
        const tracer::TileResult placed{{t.x0 - region.x0, t.y0 - region.y0, t.x1 - region.x0, t.y1 - region.y0},
                                        result.index, result.rgb};
        if (keep) keep->place(placed);
        else rows->add(placed);
        progress.update(++done, static_cast<int>(job.tiles.size()));
    };
    const tracer::RenderOutcome r = tracer::render(scene, job);
    progress.clear();
    if (interrupted.load()) {
        std::cerr << "crtc: interrupted; no image written\n";
        return 130;
    }
    if (!r.ok && !r.cancelled) {
        std::cerr << "crtc: " << r.error << "\n";
        return 1;
    }
    // A render stopped without Ctrl-C was stopped by its output's failure, which finish()
    // reports.
    std::string error;
    if (streamed && !streamed->finish(error)) {
        std::cerr << "crtc: " << error << "\n";
        return 2;
    }
    totals.add(r, static_cast<uint64_t>(width) * height);
    return 0;
}

/// Applies the command line's size and quality to an evaluated scene.
void applyCommandLine(const Options& options, scene::SceneDesc& scene) {
    if (options.width > 0) scene.settings.width = options.width;
    if (options.height > 0) scene.settings.height = options.height;
    scene::applyQuality(scene, options.quality);
}

/// How a frame is named in the progress: its number and its place in this run.
std::string frameLabel(const FrameSelection& frames, int frame) {
    if (frames.count <= 1) return "";
    if (frames.selected() == frames.count && frames.first == 0) return fmt::format("frame {}/{} ", frame + 1, frames.count);
    return fmt::format("frame {} ({}/{}) ", frame, frame - frames.begin() + 1, frames.selected());
}

} // namespace

std::string defaultOutput(const std::string& script, bool animation) {
    return fs::path(script).replace_extension(animation ? ".gif" : ".png").string();
}

bool hasFramePattern(const std::string& output) { return std::regex_search(output, framePattern()); }

std::string numberedOutput(const std::string& output, int frame) {
    std::smatch m;
    if (!std::regex_search(output, m, framePattern())) return output;
    std::string spec = m.str().substr(1, m.length() - 2); // "04" of "%04d"
    int width = 0;
    for (char c : spec) width = width * 10 + (c - '0');
    std::string number = fmt::format("{:0{}d}", frame, width);
    return m.prefix().str() + number + m.suffix().str();
}

int renderCommand(const Options& options, const CompileFrame& compileFrame) {
    const FrameSelection& frames = options.frames;
    OutputPlan plan;
    if (!planOutput(options, plan)) return 2;
    std::signal(SIGINT, onInterrupt);

    image_io::GifFrames gifFrames; // as 8-bit codes: a long animation fits in memory
    std::string previousKey;
    RenderTotals totals;
    image_io::WriteOptions write;
    if (options.pngCompression >= 0) write.pngCompression = options.pngCompression;
    ProgressReporter progress(options.quiet, frames.selected());
    const auto start = std::chrono::steady_clock::now();
    for (int frame = frames.begin(); frame < frames.end(); ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        scene::SceneDesc& scene = *c.scene;
        applyCommandLine(options, scene);
        tracer::Tile region;
        if (!renderedRegion(options, scene, region)) return 2;
        write.gamma = scene.settings.gamma;
        write.srgb = scene.settings.srgb;
        totals.width = region.width();
        totals.height = region.height();

        std::string key = frames.selected() > 1 ? sceneKey(scene) : std::string();
        const bool unchanged = frame > frames.begin() && key == previousKey;
        previousKey = std::move(key);
        progress.startFrame(frameLabel(frames, frame));
        std::string error;
        if (unchanged) {
            // Nothing the renderer sees changed since the previous frame: reuse its image
            // (a GIF repeats its codes; a numbered image is the previous file again).
            ++totals.reusedFrames;
            if (plan.gif) gifFrames.repeatLast();
            else if (!image_io::copyImage(plan.target(frame - 1), plan.target(frame), error)) {
                std::cerr << "crtc: " << error << "\n";
                return 2;
            }
            progress.finishFrame();
            continue;
        }
        std::optional<tracer::PixelBuffer> kept;
        if (plan.gif) kept.emplace(region.width(), region.height());
        if (int status = renderFrame(options, scene, region, plan.target(frame), write, progress,
                                     kept ? &*kept : nullptr, totals))
            return status;
        progress.finishFrame();
        if (plan.gif && !gifFrames.add(toBuffer(std::move(*kept)), write, error)) {
            std::cerr << fmt::format("crtc: cannot write '{}': {}\n", plan.path, error);
            return 2;
        }
    }
    std::string error;
    if (plan.gif && !image_io::writeAnimatedGif(plan.path, gifFrames, options.fps, error)) {
        std::cerr << "crtc: " << error << "\n";
        return 2;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!options.quiet) printSummary(totals, frames.selected(), seconds, plan.path);
    if (options.stats) printStats(totals);
    return 0;
}

} // namespace crt::crtc
