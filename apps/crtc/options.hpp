// Command-line options of crtc.
#pragma once

#include "interpreter.hpp"
#include "scene/quality_overrides.hpp"
#include "tracer/renderer.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crt::crtc {

enum class Mode { Render, Check, DumpAst, DumpScene, Format, Preview };
enum class ColorWhen { Auto, Always, Never };

/// The frames of an animation, and which of them this run evaluates.
struct FrameSelection {
    int count = 0; ///< --frames N; 0: a single evaluation
    int first = 0; ///< --first-frame K: the frames are numbered K .. K+N-1 (t and file numbers)
    /// --frame-range A:B, or --time with --frames: the frame numbers evaluated, both included.
    std::optional<std::pair<int, int>> range;
    double clockStart = 0, clockEnd = 1; ///< --clock A:B: clock at the first and the last frame

    bool animated() const { return count > 0; }
    int last() const { return first + std::max(count, 1) - 1; }
    int begin() const { return range ? range->first : first; }
    int end() const { return (range ? range->second : last()) + 1; }
    int selected() const { return end() - begin(); }
};

struct Options {
    Mode mode = Mode::Render;
    std::string script;
    std::string output;
    lang::EvalOptions eval;
    FrameSelection frames;
    bool werror = false;
    uint32_t maxErrors = 50; ///< errors printed before "too many errors"; 0: all
    ColorWhen color = ColorWhen::Auto;
    bool quiet = false;
    // Rendering
    int width = 0;     ///< --width; 0: the script's
    int height = 0;    ///< --height; 0: the script's
    int threads = 0;   ///< --threads; 0: all cores
    double fps = 15;   ///< --fps of an animated GIF
    int pngCompression = -1; ///< --png-compression 0-9; -1: the image writer's default
    bool stats = false; ///< --stats
    bool resume = false; ///< --continue: finish what an interrupted render of the same output began
    /// --resume-log-after: seconds a frame renders before its tiles go into the resume log
    double resumeLogAfter = 5;
    scene::QualityOverrides quality;
    std::optional<tracer::Tile> region; ///< --region: the part of the image rendered
    bool alpha = false; ///< --alpha: a fourth channel, the background transparent
    /// --time-limit: seconds a path-traced frame renders (scene build included) before it
    /// stops with the image so far; 0: no limit
    double timeLimit = 0;
    /// --aov: the buffers a path-traced render writes beside its image, NAME.exr each
    tracer::AovSet aovs;
    // Preview
    int port = 0;        ///< --port; 0: a free port
    bool open = false;   ///< --open: show the preview in the desktop's browser
};

/// The result of reading argv: options, or a message and exit status (0 for --help).
struct ParsedOptions {
    std::optional<Options> options;
    std::string message;
    int status = 0;
};

ParsedOptions parseOptions(int argc, char** argv);

/// A render job with what the options say of every render: threads, alpha, AOVs, and a time
/// limit from now.
tracer::RenderJob renderJob(const Options& options);

} // namespace crt::crtc
