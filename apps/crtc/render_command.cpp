// Rendering from crtc: frames, output naming, progress, Ctrl-C, the summary line and --stats.
#include "render_command.hpp"

#include "aov_output.hpp"

#include "distributed/distributed_render.hpp"
#include "frame_hash.hpp"
#include "progress_reporter.hpp"
#include "resume_log.hpp"
#include "row_assembler.hpp"
#include "scene/quality_overrides.hpp"
#include "scene/scene_json.hpp"
#include "stop_signals.hpp"
#include "streamed_output.hpp"
#include "terminal_text.hpp"
#include "tracer/image_io/image_io.hpp"
#include "tracer/renderer.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
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
    // One located in the script is printed as the front end's diagnostics are, for editors'
    // problem matchers; any other names crtc.
    static const std::regex located("^[^\n]+?:[0-9]+:[0-9]+: error: ");
    std::cerr << (std::regex_search(message, located) ? "" : "crtc: ")
              << lang::terminalSafe(message) << "\n";
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
        outcome.drawnPrimitives = r.drawnPrimitives;
        outcome.sceneBytes = std::max(outcome.sceneBytes, r.sceneBytes);
        outcome.peakBytes = std::max(outcome.peakBytes, r.peakBytes);
        outcome.bvhNodes = r.bvhNodes;
        outcome.bvhDepth = r.bvhDepth;
        outcome.shading = r.shading;
        // Each warning once, however many frames met it.
        for (size_t at = 0; at < r.warnings.size();) {
            const size_t end = std::min(r.warnings.find('\n', at), r.warnings.size());
            const std::string line = r.warnings.substr(at, end - at + 1);
            if (outcome.warnings.find(line) == std::string::npos) outcome.warnings += line;
            at = end + 1;
        }
    }
};

void printStats(const RenderTotals& totals) {
    constexpr double kMiB = 1 << 20;
    const tracer::RenderOutcome& r = totals.outcome;
    const tracer::RayStats& s = r.stats;
    std::cerr << fmt::format(
        "crtc: stats: primitives {} stored, {} drawn (a shared mesh or entity is stored once), "
        "BVH nodes {}, BVH depth {}\n"
        "crtc: stats: memory: scene {:.2f} MiB ({:.0f} bytes a primitive), peak {:.1f} MiB\n"
        "crtc: stats: shading: {}\n"
        "crtc: stats: rays: camera {}, reflection {}, refraction {}, shadow {} (total {})\n"
        "crtc: stats: BVH nodes visited {}, intersection tests {}\n"
        "crtc: stats: build {:.3f}s, render {:.3f}s, frames reused unchanged {}\n",
        r.primitives, r.drawnPrimitives, r.bvhNodes, r.bvhDepth, r.sceneBytes / kMiB,
        r.primitives > 0 ? double(r.sceneBytes) / double(r.primitives) : 0.0, r.peakBytes / kMiB,
        r.shading, s.cameraRays, s.reflectionRays,
        s.refractionRays, s.shadowRays, s.totalRays(), s.nodesVisited, s.intersectionTests,
        r.buildSeconds, r.renderSeconds, totals.reusedFrames);
    if (s.pathPixels > 0)
        std::cerr << fmt::format("crtc: stats: paths a pixel: fewest {}, mean {:.1f}, most {}; estimated "
                                 "relative error {:.2f} % (root mean square of the pixels')\n",
                                 s.fewestPaths, double(s.cameraRays) / double(s.pathPixels), s.mostPaths,
                                 100 * s.imageRelativeError());
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

void printSummary(const RenderTotals& totals, int frames, double seconds,
                  const std::string& output) {
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
    b.channels = frame.channels;
    b.pixels = std::move(frame.pixels);
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
    plan.path = options.output.empty()
                    ? defaultOutput(options.script, sequence && frames.selected() > 1)
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
    if (options.alpha && (plan.gif || !image_io::storesAlpha(plan.target(frames.begin())))) {
        std::cerr << fmt::format("crtc: --alpha: '{}' is of a format without an alpha channel "
                                 "(use .png, .tif or .exr)\n",
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
    std::cerr << fmt::format("crtc: --region {}:{}:{}:{} is not inside the {}x{} image\n",
                             region.x0, region.y0, region.x1, region.y1, width, height);
    return false;
}

/// One frame to render: where it goes, and what an interrupted run left of it.
struct FrameJob {
    int frame = 0;
    tracer::Tile region;
    std::string target;
    tracer::PixelBuffer* keep = nullptr; ///< a GIF's frame: kept rather than written
    const std::map<int, std::vector<float>>* loggedTiles = nullptr;
};

/// Whether the options that only path tracing has (--time-limit, --aov) fit `scene` and `job`;
/// else says why.
bool pathOptionsFit(const Options& options, const scene::SceneDesc& scene, const FrameJob& job) {
    const char* option = options.timeLimit > 0 ? "--time-limit" : !options.aovs.empty() ? "--aov" : nullptr;
    if (option && scene.settings.integrator != scene::Integrator::Path) {
        std::cerr << fmt::format("crtc: {} needs the path integrator, and this scene's is \"whitted\": add "
                                 "--integrator path, or set Settings.integrator -> \"path\"\n",
                                 option);
        return false;
    }
    if (!options.aovs.empty() && job.keep) {
        std::cerr << "crtc: --aov writes its images beside each frame's: give -o a numbered name "
                     "(out_%03d.png) rather than a GIF\n";
        return false;
    }
    return true;
}

/// Renders the region of one frame of `scene`: streamed to the file `job.target` as its rows
/// are finished, or into `job.keep`; tiles an interrupted run logged are taken from the log.
/// Returns 0 or crtc's exit status.
int renderFrame(const Options& options, const scene::SceneDesc& scene, const FrameJob& job,
                const image_io::WriteOptions& write, ProgressReporter& progress, ResumeLog* log,
                RenderTotals& totals, const TileRenderer& renderTiles) {
    if (!pathOptionsFit(options, scene, job)) return 2;
    tracer::RenderJob render = renderJob(options);
    const tracer::Tile& region = job.region;
    const int width = region.width(), height = region.height();
    const int channels = render.channels();
    std::optional<StreamedOutput> streamed;
    std::optional<RowAssembler> rows;
    if (!job.keep) {
        streamed.emplace(job.target, width, height, render.colorChannels(), write, stopRendering);
        rows.emplace(width, height, render.colorChannels(), [&](int yBegin, int yEnd, std::span<const float> pixels) {
            streamed->addRows(yBegin, yEnd, pixels);
        });
    }
    std::optional<AovOutput> aovs;
    if (!options.aovs.empty()) aovs.emplace(job.target, width, height, render.colorChannels(), options.aovs);
    std::vector<float> color;
    const std::vector<tracer::Tile> tiles = tracer::regionTiles(region);
    int done = 0;
    // The output image is the region alone: its tiles move to its top left corner.
    auto deliver = [&](const tracer::TileResult& result) {
        const tracer::Tile& t = result.tile;
        const tracer::TileResult placed{
            {t.x0 - region.x0, t.y0 - region.y0, t.x1 - region.x0, t.y1 - region.y0},
            result.index,
            result.channels,
            result.pixels};
        const tracer::TileResult shown = aovs ? aovs->take(placed, color) : placed;
        if (job.keep)
            job.keep->place(shown);
        else
            rows->add(shown);
        progress.update(++done, static_cast<int>(tiles.size()));
    };
    std::vector<int> tileIndex; // of each tile of the render job in `tiles`
    uint64_t tracedPixels = 0;
    for (int i = 0; i < static_cast<int>(tiles.size()); ++i) {
        const tracer::Tile& tile = tiles[static_cast<size_t>(i)];
        const std::vector<float>* logged = nullptr;
        if (job.loggedTiles) {
            auto found = job.loggedTiles->find(i);
            if (found != job.loggedTiles->end() &&
                found->second.size() == static_cast<size_t>(tile.width()) * tile.height() * channels)
                logged = &found->second;
        }
        if (logged) {
            deliver(tracer::TileResult{tile, i, channels, *logged});
            continue;
        }
        render.tiles.push_back(tile);
        tileIndex.push_back(i);
        tracedPixels += static_cast<uint64_t>(tile.width()) * tile.height();
    }
    if (done > 0 && !options.quiet) {
        progress.clear();
        std::cerr << fmt::format("crtc: continuing {}: {} of {} tiles were rendered before\n",
                                 job.target, done, tiles.size());
    }
    render.cancel = &stopRendering;
    render.onTileDone = [&](const tracer::TileResult& result) {
        const tracer::TileResult indexed{result.tile, tileIndex[static_cast<size_t>(result.index)],
                                         result.channels, result.pixels};
        if (log) log->addTile(job.frame, indexed);
        deliver(indexed);
    };
    const tracer::RenderOutcome r = renderTiles(scene, render);
    progress.clear();
    if (!r.ok && !r.cancelled) {
        printError(r.error);
        return 1;
    }
    // A cancelled render was stopped by its output's failure, which finish() reports.
    std::string error;
    if ((streamed && !streamed->finish(error)) || (aovs && !aovs->write(error))) {
        printError(error);
        return 2;
    }
    totals.add(r, tracedPixels);
    return 0;
}

/// How a frame is named in the progress: its number and its place in this run.
std::string frameLabel(const FrameSelection& frames, int frame) {
    if (frames.count <= 1) return "";
    if (frames.selected() == frames.count && frames.first == 0)
        return fmt::format("frame {}/{} ", frame + 1, frames.count);
    return fmt::format("frame {} ({}/{}) ", frame, frame - frames.begin() + 1, frames.selected());
}

} // namespace

void applyCommandLine(const Options& options, scene::SceneDesc& scene) {
    if (options.width > 0) scene.settings.width = options.width;
    if (options.height > 0) scene.settings.height = options.height;
    scene::applyQuality(scene, options.quality);
}

std::string defaultOutput(const std::string& script, bool animation) {
    return fs::path(script).replace_extension(animation ? ".gif" : ".png").string();
}

bool hasFramePattern(const std::string& output) {
    return std::regex_search(output, framePattern());
}

std::string numberedOutput(const std::string& output, int frame) {
    std::smatch m;
    if (!std::regex_search(output, m, framePattern())) return output;
    std::string spec = m.str().substr(1, m.length() - 2); // "04" of "%04d"
    int width = 0;
    for (char c : spec) width = width * 10 + (c - '0');
    std::string number = fmt::format("{:0{}d}", frame, width);
    return m.prefix().str() + number + m.suffix().str();
}

namespace {

/// A run of crtc's render mode: the frames selected, their output, and the resume log.
class RenderRun {
  public:
    RenderRun(const Options& options, OutputPlan plan, const TileRenderer& renderTiles)
        : options_(options), frames_(options.frames), plan_(std::move(plan)),
          progress_(options.quiet, options.frames.selected()), renderTiles_(renderTiles) {
        if (options.pngCompression >= 0) write_.pngCompression = options.pngCompression;
    }

    int run(const CompileFrame& compileFrame);
    /// Takes the frames from `feed` rather than evaluating them (run's compileFrame unused).
    void feedFrom(FrameFeed& feed) { feed_ = &feed; }

  private:
    int openLog();
    int renderOne(int frame, const Compilation& c, scene::SceneDesc& scene);
    int reuseUnchanged(int frame);
    void updateStopNote();
    int failed(int status);
    bool finishedBefore(int frame, uint64_t hash) const;
    bool evaluate(int frame, Compilation& c, const CompileFrame& compileFrame, bool& unchanged);

    const Options& options_;
    const FrameSelection& frames_;
    OutputPlan plan_;
    ProgressReporter progress_;
    const TileRenderer& renderTiles_;
    image_io::WriteOptions write_;
    image_io::GifFrames gifFrames_; // as 8-bit codes: a long animation fits in memory
    RenderTotals totals_;
    std::optional<ResumeLog> log_; // none for a GIF, whose frames wait in memory
    std::string previousKey_;
    std::vector<int> written_; // frames whose files are complete
    bool continueRefused_ = false;
    FrameFeed* feed_ = nullptr;
    uint64_t fedHash_ = 0; // the frameHash of the frame the feed gave last
};

int RenderRun::openLog() {
    if (plan_.gif) {
        if (!options_.resume) return 0;
        std::cerr
            << "crtc: --continue cannot finish an animated GIF (its frames wait in memory); render "
               "numbered images (-o f_%04d.png) to be able to continue\n";
        return 2;
    }
    const std::string path = ResumeLog::pathFor(plan_.path);
    // Without the output's folder there is nothing to continue; the output reports it.
    if (!options_.resume &&
        !fs::is_directory(fs::path(path).parent_path().empty() ? "."
                                                               : fs::path(path).parent_path()))
        return 0;
    log_.emplace();
    std::string error;
    if (options_.resume) {
        if (!log_->load(path, error)) {
            std::cerr << "crtc: cannot continue: " << error << "\n";
            return 2;
        }
        if (log_->frames().empty()) {
            std::cerr << fmt::format(
                "crtc: nothing to continue: no interrupted render of '{}' (its log '{}' "
                "does not exist); render without --continue\n",
                plan_.path, path);
            return 2;
        }
    }
    // A continued render rewrites its log at once, so that a log it cannot write is said
    // before any work.
    log_->prepare(path, options_.resume,
                  std::chrono::duration_cast<ResumeLog::Clock::duration>(
                      std::chrono::duration<double>(options_.resumeLogAfter)),
                  [this] { updateStopNote(); });
    if (options_.resume && !log_->start(error)) {
        printError(error);
        return 2;
    }
    return 0;
}

/// A run that failed (not one a signal stopped, which keeps its log for --continue): its log
/// goes, as it would only take room on what is often a full disk.
int RenderRun::failed(int status) {
    if (log_ && !continueRefused_) log_->remove();
    return status;
}

/// What a signal that stops the run now leaves (printed by the stop handler): what was
/// written, and how to go on.
void RenderRun::updateStopNote() {
    std::string written = "no image written";
    if (!written_.empty() && plan_.numbered)
        written =
            fmt::format("frames {} to {} written ({} to {})", written_.front(), written_.back(),
                        plan_.target(written_.front()), plan_.target(written_.back()));
    setStopNote(fmt::format("crtc: interrupted; {}{}\n", written,
                            log_ && log_->started()
                                ? "; crtc --continue with the same options finishes the render"
                                : ""));
}

int RenderRun::reuseUnchanged(int frame) {
    // Nothing the renderer sees changed since the previous frame: reuse its image (a GIF
    // repeats its codes; a numbered image is the previous file again).
    ++totals_.reusedFrames;
    std::string error;
    if (plan_.gif)
        gifFrames_.repeatLast();
    else if (!image_io::copyImage(plan_.target(frame - 1), plan_.target(frame), error)) {
        printError(error);
        return 2;
    }
    return 0;
}

int RenderRun::renderOne(int frame, const Compilation& c, scene::SceneDesc& scene) {
    FrameJob job;
    job.frame = frame;
    job.target = plan_.target(frame);
    if (!renderedRegion(options_, scene, job.region)) return 2;
    write_.gamma = scene.settings.gamma;
    write_.srgb = scene.settings.srgb;
    totals_.width = job.region.width();
    totals_.height = job.region.height();
    if (log_) {
        const uint64_t hash = feed_ ? fedHash_ : frameHash(c, scene, options_, job.region);
        auto logged = log_->frames().find(frame);
        if (options_.resume && logged != log_->frames().end()) {
            if (logged->second.sceneHash != hash) {
                std::cerr << fmt::format(
                    "crtc: cannot continue: frame {} is not the frame the interrupted render "
                    "began (the script, a file it reads, an option or crtc changed); render "
                    "it again without --continue\n",
                    frame);
                continueRefused_ = true; // the log stays: the change may be undone
                return 2;
            }
            if (logged->second.done && fs::exists(job.target)) return -1; // finished before
            job.loggedTiles = &logged->second.tiles;
        }
        log_->beginFrame(frame, hash);
    }
    std::optional<tracer::PixelBuffer> kept;
    if (plan_.gif) job.keep = &kept.emplace(job.region.width(), job.region.height());
    if (int status =
            renderFrame(options_, scene, job, write_, progress_, log_ ? &*log_ : nullptr, totals_,
                        renderTiles_))
        return status;
    std::string error;
    if (plan_.gif && !gifFrames_.add(toBuffer(std::move(*kept)), write_, error)) {
        printError(fmt::format("cannot write '{}': {}", plan_.path, error));
        return 2;
    }
    return 0;
}

/// Evaluates `frame` into `c`, or takes it from the feed: then `c` has no script, and its scene
/// only the settings the run reads (size, gamma).
bool RenderRun::evaluate(int frame, Compilation& c, const CompileFrame& compileFrame,
                         bool& unchanged) {
    if (feed_) {
        const FedFrame fed = feed_->next(frame);
        if (!fed.ok) return false;
        scene::SceneDesc& scene = c.scene.emplace();
        scene.settings.width = fed.width;
        scene.settings.height = fed.height;
        scene.settings.gamma = fed.gamma;
        scene.settings.srgb = fed.srgb;
        unchanged = fed.unchanged;
        fedHash_ = fed.hash;
        return true;
    }
    if (!compileFrame(frame, c)) return false;
    scene::SceneDesc& scene = *c.scene;
    applyCommandLine(options_, scene);
    std::string key = frames_.selected() > 1 ? sceneKey(scene) : std::string();
    unchanged = frame > frames_.begin() && key == previousKey_;
    previousKey_ = std::move(key);
    return true;
}

/// Whether --continue finds `frame` finished by the interrupted run (renderOne's test, before
/// the frame is traced).
bool RenderRun::finishedBefore(int frame, uint64_t hash) const {
    if (!log_ || !options_.resume) return false;
    auto logged = log_->frames().find(frame);
    return logged != log_->frames().end() && logged->second.sceneHash == hash &&
           logged->second.done && fs::exists(plan_.target(frame));
}

int RenderRun::run(const CompileFrame& compileFrame) {
    if (int status = openLog()) return status;
    if (feed_) feed_->begin([this](int frame, uint64_t hash) { return finishedBefore(frame, hash); });
    updateStopNote();
    const auto start = std::chrono::steady_clock::now();
    for (int frame = frames_.begin(); frame < frames_.end(); ++frame) {
        Compilation c;
        bool unchanged = false;
        if (!evaluate(frame, c, compileFrame, unchanged)) return failed(1);
        scene::SceneDesc& scene = *c.scene;
        progress_.startFrame(frameLabel(frames_, frame));
        const int status = unchanged ? reuseUnchanged(frame) : renderOne(frame, c, scene);
        if (status > 0) return failed(status);
        // The file is in place: a signal from now on must name it, also while the log is
        // synced to disk (which can take a while on a busy one).
        written_.push_back(frame);
        updateStopNote();
        progress_.finishFrame();
        // After the last frame the log goes: a record of it would only create the file.
        if (log_ && frame + 1 < frames_.end()) log_->frameDone(frame);
    }
    std::string error;
    if (plan_.gif && !image_io::writeAnimatedGif(plan_.path, gifFrames_, options_.fps, error)) {
        printError(error);
        return 2;
    }
    if (log_) log_->remove();
    std::cerr << lang::terminalSafe(totals_.outcome.warnings); // diagnostics: -q keeps them
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!options_.quiet) printSummary(totals_, frames_.selected(), seconds, plan_.path);
    if (options_.stats) printStats(totals_);
    return 0;
}

} // namespace

int renderFrames(const Options& options, const CompileFrame& compileFrame,
                 const TileRenderer& renderTiles) {
    OutputPlan plan;
    if (!planOutput(options, plan)) return 2;
    return RenderRun(options, std::move(plan), renderTiles).run(compileFrame);
}

int renderFedFrames(const Options& options, FrameFeed& feed) {
    OutputPlan plan;
    if (!planOutput(options, plan)) return 2;
    const TileRenderer fromFeed = [&feed](const scene::SceneDesc&, const tracer::RenderJob& job) {
        return feed.render(job);
    };
    RenderRun run(options, std::move(plan), fromFeed);
    run.feedFrom(feed);
    return run.run([](int, Compilation&) { return false; });
}

std::string unchangedFrameKey(const scene::SceneDesc& scene) { return sceneKey(scene); }

int renderCommand(const Options& options, const CompileFrame& compileFrame) {
    if (distributed::underMpi()) return distributed::renderDistributed(options, compileFrame);
    return renderFrames(options, compileFrame, renderTilesHere);
}

tracer::RenderOutcome renderTilesHere(const scene::SceneDesc& scene, const tracer::RenderJob& job) {
    tracer::RenderOutcome r;
    r.ok = true;
    // Empty tiles would mean the whole image to the renderer: here, the log had every tile.
    if (!job.tiles.empty()) r = tracer::render(scene, job);
    return r;
}

} // namespace crt::crtc
