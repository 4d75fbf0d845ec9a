// Rendering from crtc: frames, output naming, progress, Ctrl-C, the summary line and --stats.
#include "render_command.hpp"

#include "scene_json.hpp"
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
#include <unistd.h>

namespace crt::lang::driver {

namespace fs = std::filesystem;
namespace image_io = tracer::image_io;

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

/// Prints progress: a bar on a terminal, a line per 10 % otherwise, nothing when quiet.
class ProgressReporter {
public:
    ProgressReporter(bool quiet, std::string label) : quiet_(quiet), label_(std::move(label)), tty_(isatty(STDERR_FILENO)) {}

    void update(int done, int total) {
        if (quiet_ || total == 0) return;
        double fraction = static_cast<double>(done) / total;
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (tty_) {
            int filled = static_cast<int>(fraction * 30);
            std::string remaining = done > 0 ? fmt::format("{:.1f}s", elapsed / fraction - elapsed) : "?";
            std::cerr << fmt::format("\r{}[{:<30}] {:3.0f}%  elapsed {:.1f}s  remaining {}   ", label_,
                                     std::string(filled, '#'), fraction * 100, elapsed, remaining)
                      << std::flush;
            drawn_ = true;
        } else {
            int tenth = static_cast<int>(fraction * 10);
            if (tenth > lastTenth_) {
                lastTenth_ = tenth;
                std::cerr << fmt::format("crtc: {}{}% ({:.1f}s)\n", label_, tenth * 10, elapsed);
            }
        }
    }
    void finish() {
        if (drawn_) std::cerr << "\r" << std::string(80 + label_.size(), ' ') << "\r" << std::flush;
    }

private:
    bool quiet_;
    std::string label_;
    bool tty_;
    bool drawn_ = false;
    int lastTenth_ = 0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void printStats(const tracer::RenderOutcome& r, uint64_t cachedFrames) {
    const tracer::RayStats& s = r.stats;
    std::cerr << fmt::format(
        "crtc: stats: primitives {}, BVH nodes {}, BVH depth {}\n"
        "crtc: stats: rays: camera {}, reflection {}, refraction {}, shadow {} (total {})\n"
        "crtc: stats: BVH nodes visited {}, intersection tests {}\n"
        "crtc: stats: build {:.3f}s, render {:.3f}s, frames reused unchanged {}\n",
        r.primitives, r.bvhNodes, r.bvhDepth, s.cameraRays, s.reflectionRays, s.refractionRays, s.shadowRays, s.totalRays(),
        s.nodesVisited, s.intersectionTests, r.buildSeconds, r.renderSeconds, cachedFrames);
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
std::string sceneKey(tracer::SceneDesc scene) {
    scene.time = 0;
    scene.frame = 0;
    return sceneToJson(scene);
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
    int frames = std::max(options.frames, 1);
    std::string output = options.output.empty() ? defaultOutput(options.script, frames) : options.output;
    bool numbered = frames > 1 && hasFramePattern(output);
    bool gif = frames > 1 && !numbered;
    if (gif && fs::path(output).extension() != ".gif") {
        std::cerr << "crtc: with --frames, -o must end in .gif or contain a frame number pattern such as %04d\n";
        return 2;
    }
    if (!image_io::isSupportedOutput(numbered ? numberedOutput(output, 0) : output)) {
        std::cerr << fmt::format("crtc: cannot write '{}': unknown image format (use .png, .jpg, .tif, .exr, .hdr or .gif)\n", output);
        return 2;
    }
    std::signal(SIGINT, onInterrupt);

    image_io::GifFrames gifFrames; // as 8-bit codes: a long animation fits in memory
    std::string previousKey;
    std::string previousTarget; // for numbered frames: an unchanged frame copies its file
    tracer::RenderOutcome total;
    uint64_t cachedFrames = 0;
    image_io::WriteOptions write;
    if (options.pngCompression >= 0) write.pngCompression = options.pngCompression;
    auto start = std::chrono::steady_clock::now();
    int width = 0, height = 0;
    uint64_t samples = 0;
    for (int frame = 0; frame < frames; ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        tracer::SceneDesc& scene = *c.scene;
        if (options.width > 0) scene.settings.width = options.width;
        if (options.height > 0) scene.settings.height = options.height;
        uint32_t maxSize = options.eval.limits.maxSize;
        if (static_cast<uint32_t>(scene.settings.width) > maxSize || static_cast<uint32_t>(scene.settings.height) > maxSize) {
            std::cerr << fmt::format("crtc: image size {}x{} is above the limit {} (raise it with --max-size)\n",
                                     scene.settings.width, scene.settings.height, maxSize);
            return 2;
        }
        write.gamma = scene.settings.gamma;
        write.srgb = scene.settings.srgb;
        width = scene.settings.width;
        height = scene.settings.height;

        image_io::ImageBuffer image;
        const std::string target = numbered ? numberedOutput(output, frame) : output;
        std::string key = frames > 1 ? sceneKey(scene) : std::string();
        const bool unchanged = frame > 0 && key == previousKey;
        if (unchanged) {
            // Nothing the renderer sees changed since the previous frame: reuse its image
            // (a GIF repeats its codes below; a numbered image is the previous file again).
            std::string error;
            if (numbered && !image_io::copyImage(previousTarget, target, error)) {
                std::cerr << "crtc: " << error << "\n";
                return 2;
            }
            ++cachedFrames;
        } else {
            ProgressReporter progress(options.quiet, frames > 1 ? fmt::format("frame {}/{} ", frame + 1, frames) : "");
            tracer::RenderSettings settings;
            settings.threads = options.threads;
            settings.cancel = &stopRendering;
            if (!options.quiet) settings.onProgress = [&](int done, int all) { progress.update(done, all); };
            // An output that needs the image module (OpenImageIO, about 0.2 s to load; a PNG
            // does not) has it loaded while the frame is traced; not earlier, since no thread
            // can start while it loads.
            if (image_io::writingNeedsModule(output)) {
                settings.onThreadsStarted = [] { image_io::startLoading(); };
                settings.beforeLastWorker = [] { image_io::finishLoading(); };
            }
            std::optional<StreamedOutput> streamed;
            if (!gif) {
                streamed.emplace(target, width, height, write, stopRendering);
                settings.onRowsDone = [&](int yBegin, int yEnd, std::span<const float> rgb) {
                    streamed->addRows(yBegin, yEnd, rgb);
                };
                // Streamed images are not read back: an unchanged next frame copies the file.
                settings.keepFrame = false;
            }
            tracer::RenderOutcome r = tracer::renderScene(scene, settings);
            progress.finish();
            if (interrupted.load()) {
                std::cerr << "crtc: interrupted; no image written\n";
                return 130;
            }
            if (!r.ok && !r.cancelled) {
                std::cerr << "crtc: " << r.error << "\n";
                return 1;
            }
            // A render stopped without Ctrl-C was stopped by its output's failure, which
            // finish() reports.
            std::string error;
            if (streamed && !streamed->finish(error)) {
                std::cerr << "crtc: " << error << "\n";
                return 2;
            }
            samples = r.samples;
            total.stats += r.stats;
            total.buildSeconds += r.buildSeconds;
            total.renderSeconds += r.renderSeconds;
            total.primitives = r.primitives;
            total.bvhNodes = r.bvhNodes;
            total.bvhDepth = r.bvhDepth;
            if (gif) image = toBuffer(std::move(r.frame)); // other images were streamed
        }
        previousKey = std::move(key);
        previousTarget = target;
        std::string error;
        if (gif && unchanged) {
            gifFrames.repeatLast();
        } else if (gif && !gifFrames.add(image, write, error)) {
            std::cerr << fmt::format("crtc: cannot write '{}': {}\n", output, error);
            return 2;
        }
    }
    if (gif) {
        std::string error;
        if (!image_io::writeAnimatedGif(output, gifFrames, options.fps, error)) {
            std::cerr << "crtc: " << error << "\n";
            return 2;
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!options.quiet) {
        double mrays = total.renderSeconds > 0 ? total.stats.totalRays() / total.renderSeconds / 1e6 : 0;
        std::cerr << fmt::format("crtc: {}x{}, {} sample{}/pixel{}, {:.2f}s, {:.1f} Mrays/s -> {}\n", width, height,
                                 samples, samples == 1 ? "" : "s",
                                 frames > 1 ? fmt::format(", {} frames", frames) : "", seconds, mrays, output);
    }
    if (options.stats) printStats(total, cachedFrames);
    return 0;
}

} // namespace crt::lang::driver
