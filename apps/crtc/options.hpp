// Command-line options of crtc.
#pragma once

#include "interpreter.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crt::crtc {

enum class Mode { Render, Check, DumpAst, DumpScene, Format, Preview };
enum class ColorWhen { Auto, Always, Never };

struct Options {
    Mode mode = Mode::Render;
    std::string script;
    std::string output;
    lang::EvalOptions eval;
    int frames = 0; ///< --frames N; 0: a single evaluation
    bool werror = false;
    ColorWhen color = ColorWhen::Auto;
    bool quiet = false;
    // Rendering
    int width = 0;     ///< --width; 0: the script's
    int height = 0;    ///< --height; 0: the script's
    int threads = 0;   ///< --threads; 0: all cores
    double fps = 15;   ///< --fps of an animated GIF
    int pngCompression = -1; ///< --png-compression 0-9; -1: the image writer's default
    bool stats = false; ///< --stats
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
std::string usage();

} // namespace crt::crtc
