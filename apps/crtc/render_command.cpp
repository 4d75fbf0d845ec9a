// Rendering from crtc: frames, output naming, progress, Ctrl-C, the summary line and --stats.
#include "render_command.hpp"

#include "progress_reporter.hpp"
#include "row_assembler.hpp"
#include "stop_signals.hpp"
#include "scene/scene_json.hpp"
#include "streamed_output.hpp"
#include "terminal_text.hpp"
#include "tracer/image_io/image_io.hpp"
#include "tracer/renderer.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>

namespace crt::crtc {

namespace fs = std::filesystem;
namespace image_io = tracer::image_io;
using lang::Compilation;

namespace {

/// Set by an output that failed: the rest of the render is of no use.
std::atomic<bool> stopRendering{false};

/// Prints "crtc: " and the message, which can quote a script's bytes (an OBJ file's token, a
/// file name), escaped for the terminal.
void printError(const std::string& message) {
    std::cerr << "crtc: " << lang::terminalSafe(message) << "\n";
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
    uint64_t samples = 0;
    int width = 0, height = 0;

    void add(const tracer::RenderOutcome& r) {
        samples = r.samples;
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

void printSummary(const RenderTotals& totals, int frames, double seconds, const std::string& output) {
    const tracer::RenderOutcome& r = totals.outcome;
    const double mrays = r.renderSeconds > 0 ? r.stats.totalRays() / r.renderSeconds / 1e6 : 0;
    std::cerr << fmt::format("crtc: {}x{}, {} sample{}/pixel{}, {:.2f}s, {:.1f} Mrays/s -> {}\n",
                             totals.width, totals.height, totals.samples,
                             totals.samples == 1 ? "" : "s",
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

/// What an interruption after frame `last` of a numbered sequence leaves: the files before it.
std::string framesWrittenNote(const OutputPlan& plan, int last, int frames) {
    return fmt::format("crtc: interrupted; frames 0 to {} of {} were written ({} to {}), no "
                       "others\n",
                       last, frames, plan.target(0), plan.target(last));
}

/// Checks the output name against the frame count; false, having said why, for a name
/// crtc cannot write.
bool planOutput(const Options& options, int frames, OutputPlan& plan) {
    plan.path = options.output.empty() ? defaultOutput(options.script, frames) : options.output;
    plan.numbered = frames > 1 && hasFramePattern(plan.path);
    plan.gif = frames > 1 && !plan.numbered;
    if (plan.gif && fs::path(plan.path).extension() != ".gif") {
        std::cerr << "crtc: with --frames, -o must end in .gif or contain a frame number pattern "
                     "such as %04d\n";
        return false;
    }
    if (!image_io::isSupportedOutput(plan.target(0))) {
        std::cerr << fmt::format("crtc: cannot write '{}': unknown image format (use .png, .jpg, "
                                 ".tif, .exr, .hdr or .gif)\n",
                                 plan.path);
        return false;
    }
    return true;
}

/// Renders one frame of `scene`: streamed to the file `target` as its rows are finished, or,
/// with `keep`, into `keep` only. Returns 0 or crtc's exit status.
int renderFrame(const Options& options, const scene::SceneDesc& scene, const std::string& target,
                const image_io::WriteOptions& write, const std::string& label,
                tracer::PixelBuffer* keep, RenderTotals& totals) {
    const int width = scene.settings.width, height = scene.settings.height;
    ProgressReporter progress(options.quiet, label);
    std::optional<StreamedOutput> streamed;
    std::optional<RowAssembler> rows;
    if (!keep) {
        streamed.emplace(target, width, height, write, stopRendering);
        rows.emplace(width, height, [&](int yBegin, int yEnd, std::span<const float> rgb) {
            streamed->addRows(yBegin, yEnd, rgb);
        });
    }
    tracer::RenderJob job;
    job.tiles = tracer::imageTiles(width, height);
    job.threads = options.threads;
    job.cancel = &stopRendering;
    int done = 0;
    job.onTileDone = [&](const tracer::TileResult& tile) {
        if (keep) keep->place(tile);
        else rows->add(tile);
        progress.update(++done, static_cast<int>(job.tiles.size()));
    };
    const tracer::RenderOutcome r = tracer::render(scene, job);
    progress.finish();
    if (!r.ok && !r.cancelled) {
        printError(r.error);
        return 1;
    }
    // A cancelled render was stopped by its output's failure, which finish() reports.
    std::string error;
    if (streamed && !streamed->finish(error)) {
        printError(error);
        return 2;
    }
    totals.add(r);
    return 0;
}

} // namespace

std::string defaultOutput(const std::string& script, int frames) {
    return fs::path(script).replace_extension(frames > 1 ? ".gif" : ".png").string();
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
    const int frames = std::max(options.frames, 1);
    OutputPlan plan;
    if (!planOutput(options, frames, plan)) return 2;
    setStopNote("crtc: interrupted; no image written\n");

    image_io::GifFrames gifFrames; // as 8-bit codes: a long animation fits in memory
    std::string previousKey;
    RenderTotals totals;
    image_io::WriteOptions write;
    if (options.pngCompression >= 0) write.pngCompression = options.pngCompression;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < frames; ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        scene::SceneDesc& scene = *c.scene;
        if (options.width > 0) scene.settings.width = options.width;
        if (options.height > 0) scene.settings.height = options.height;
        write.gamma = scene.settings.gamma;
        write.srgb = scene.settings.srgb;
        totals.width = scene.settings.width;
        totals.height = scene.settings.height;

        std::string key = frames > 1 ? sceneKey(scene) : std::string();
        const bool unchanged = frame > 0 && key == previousKey;
        previousKey = std::move(key);
        std::string error;
        if (unchanged) {
            // Nothing the renderer sees changed since the previous frame: reuse its image
            // (a GIF repeats its codes; a numbered image is the previous file again).
            ++totals.reusedFrames;
            if (plan.gif) gifFrames.repeatLast();
            else if (!image_io::copyImage(plan.target(frame - 1), plan.target(frame), error)) {
                printError(error);
                return 2;
            }
            if (plan.numbered) setStopNote(framesWrittenNote(plan, frame, frames));
            continue;
        }
        const std::string label = frames > 1 ? fmt::format("frame {}/{} ", frame + 1, frames) : "";
        std::optional<tracer::PixelBuffer> kept;
        if (plan.gif) kept.emplace(scene.settings.width, scene.settings.height);
        if (int status = renderFrame(options, scene, plan.target(frame), write, label,
                                     kept ? &*kept : nullptr, totals))
            return status;
        if (plan.numbered) setStopNote(framesWrittenNote(plan, frame, frames));
        if (plan.gif && !gifFrames.add(toBuffer(std::move(*kept)), write, error)) {
            printError(fmt::format("cannot write '{}': {}", plan.path, error));
            return 2;
        }
    }
    std::string error;
    if (plan.gif && !image_io::writeAnimatedGif(plan.path, gifFrames, options.fps, error)) {
        printError(error);
        return 2;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!options.quiet) printSummary(totals, frames, seconds, plan.path);
    if (options.stats) printStats(totals);
    return 0;
}

} // namespace crt::crtc
