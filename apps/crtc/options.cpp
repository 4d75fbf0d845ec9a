// Parsing crtc's command line.
#include "options.hpp"

#include <charconv>
#include <fmt/format.h>

namespace crt::crtc {

std::string usage() {
    return R"(usage: crtc [options] script.crt

Evaluates a CRT scene script and renders it.

modes:
  --check              report diagnostics only
  --dump-ast           print the syntax tree
  --dump-scene         print the evaluated scene as JSON (docs/scene-json.md)
  --format             print the script formatted (to -o FILE if given); a script
                       with syntax errors is refused
  --preview            serve a live preview with a mouse-driven camera on
                       127.0.0.1 and print its URL (docs/preview.md)

options:
  -o FILE              output image (default: the script's name with .png, or .gif
                       with --frames); the extension picks the format: .png .jpg .tif
                       .exr .hdr .gif; with --frames, a name with %d or %04d writes
                       numbered images instead of an animated GIF
  --width N, --height N  override the script's image size
  --threads N          render threads (default: all cores)
  --fps F              frames per second of an animated GIF (default 15)
  --png-compression N  zlib level of PNG output, 0 (fastest) to 9 (smallest);
                       default 2
  --port N             --preview: listen on port N (default: a free port)
  --open               --preview: open the URL with xdg-open
  --stats              print ray and acceleration-structure counts after rendering
  -I DIR               add DIR to the include search path (repeatable)
  --assets DIR         asset root for "/..." image and mesh paths (repeatable)
  --time T             evaluate with t = T (a float)
  --frames N           evaluate N frames, t = 0 .. N-1
  --seed S             seed of rand() (default 0)
  --max-steps N        evaluation steps: loop iterations and macro calls (default 50000000)
  --max-depth N        nested macro calls (default 1000)
  --max-entities N     drawn entities and list length (default 10000000)
  --max-size N         image width and height (default 16384)
  -Werror              treat warnings as errors
  --color WHEN         color diagnostics: auto, always or never (default auto)
  -q, --quiet          print nothing but diagnostics (no progress, no summary)
  -h, --help           show this help
  --version            show the version

exit status: 0 success, 1 errors in the script, 2 bad usage or I/O failure,
             130 interrupted (Ctrl-C; no partial image is left)
)";
}

namespace {

constexpr uint32_t kMaxSupportedDepth = 200'000;

template <typename T> bool parseNumber(std::string_view text, T& out) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size();
}

/// The arguments after the program name, one at a time, and what went wrong with them.
class Arguments {
public:
    Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}

    bool done() const { return next_ >= argc_; }
    std::string_view next() { return argv_[next_++]; }
    /// The option's value, the next argument; false if there is none.
    bool value(std::string_view& out) {
        if (done()) return false;
        out = next();
        return true;
    }
    /// The value parsed as a number; false if there is none or it is not one.
    template <typename T> bool number(T& out) {
        std::string_view text;
        return value(text) && parseNumber(text, out);
    }
    /// Records the first problem; returns true, so that an option handler can end with it.
    bool fail(std::string message) {
        if (error.empty()) error = std::move(message);
        return true;
    }

    std::string error;

private:
    int argc_;
    char** argv_;
    int next_ = 1;
};

/// Modes and what is printed: true if `arg` is one of them.
bool modeOption(std::string_view arg, Arguments& args, Options& o) {
    std::string_view v;
    if (arg == "--check") o.mode = Mode::Check;
    else if (arg == "--dump-ast") o.mode = Mode::DumpAst;
    else if (arg == "--dump-scene") o.mode = Mode::DumpScene;
    else if (arg == "--format") o.mode = Mode::Format;
    else if (arg == "-Werror") o.werror = true;
    else if (arg == "-q" || arg == "--quiet") o.quiet = true;
    else if (arg == "--stats") o.stats = true;
    else if (arg == "--color" || arg.starts_with("--color=")) {
        if (arg == "--color" && !args.value(v)) return args.fail("--color needs auto, always or never");
        if (arg != "--color") v = arg.substr(8);
        if (v == "auto") o.color = ColorWhen::Auto;
        else if (v == "always") o.color = ColorWhen::Always;
        else if (v == "never") o.color = ColorWhen::Never;
        else return args.fail(fmt::format("--color takes auto, always or never, not '{}'", v));
    } else return false;
    return true;
}

/// The image and how it is rendered: true if `arg` is one of these options.
bool renderOption(std::string_view arg, Arguments& args, Options& o) {
    std::string_view v;
    if (arg == "-o") {
        if (!args.value(v)) return args.fail("-o needs a file name");
        o.output = v;
    } else if (arg == "--frames") {
        if (!args.number(o.frames) || o.frames < 1) return args.fail("--frames needs a positive integer");
    } else if (arg == "--width" || arg == "--height") {
        int& size = arg == "--width" ? o.width : o.height;
        if (!args.number(size) || size < 1) return args.fail(fmt::format("{} needs a positive integer", arg));
    } else if (arg == "--threads") {
        if (!args.number(o.threads) || o.threads < 1) return args.fail("--threads needs a positive integer");
    } else if (arg == "--fps") {
        if (!args.number(o.fps) || !(o.fps > 0) || o.fps > 100) return args.fail("--fps needs a number in (0, 100]");
    } else if (arg == "--png-compression") {
        if (!args.number(o.pngCompression) || o.pngCompression < 0 || o.pngCompression > 9)
            return args.fail("--png-compression needs an integer from 0 to 9");
    } else return false;
    return true;
}

/// The live preview: true if `arg` is one of its options.
bool previewOption(std::string_view arg, Arguments& args, Options& o) {
    if (arg == "--preview") o.mode = Mode::Preview;
    else if (arg == "--open") o.open = true;
    else if (arg == "--port") {
        if (!args.number(o.port) || o.port < 1 || o.port > 65535) return args.fail("--port needs a port number from 1 to 65535");
    } else return false;
    return true;
}

/// How the script is evaluated, and its limits: true if `arg` is one of these options.
bool evalOption(std::string_view arg, Arguments& args, Options& o) {
    std::string_view v;
    lang::EvalOptions& eval = o.eval;
    if (arg.starts_with("-I")) {
        if (arg.size() > 2) eval.includes.dirs.emplace_back(arg.substr(2));
        else if (!args.value(v)) return args.fail("-I needs a folder");
        else eval.includes.dirs.emplace_back(v);
    } else if (arg == "--assets") {
        if (!args.value(v)) return args.fail("--assets needs a folder");
        eval.assetRoots.emplace_back(v);
    } else if (arg == "--time") {
        double t = 0;
        if (!args.number(t)) return args.fail("--time needs a number");
        eval.time = t;
    } else if (arg == "--seed") {
        if (!args.number(eval.seed)) return args.fail("--seed needs a non-negative integer");
    } else if (arg == "--max-steps") {
        if (!args.number(eval.limits.maxSteps)) return args.fail("--max-steps needs a non-negative integer");
    } else if (arg == "--max-depth") {
        if (!args.number(eval.limits.maxDepth)) return args.fail("--max-depth needs a non-negative integer");
        // The front end's stack holds this many nested calls.
        if (eval.limits.maxDepth > kMaxSupportedDepth)
            return args.fail(fmt::format("--max-depth above {} is not supported", kMaxSupportedDepth));
    } else if (arg == "--max-entities") {
        if (!args.number(eval.limits.maxEntities)) return args.fail("--max-entities needs a non-negative integer");
    } else if (arg == "--max-size") {
        if (!args.number(eval.limits.maxSize) || eval.limits.maxSize == 0)
            return args.fail("--max-size needs a positive integer");
    } else return false;
    return true;
}

/// What no single option can check.
std::string checkCombination(const Options& o) {
    if (o.script.empty()) return "no script given";
    if (o.frames > 0 && o.eval.time) return "--time and --frames cannot be combined";
    if ((o.port != 0 || o.open) && o.mode != Mode::Preview) return "--port and --open need --preview";
    const uint32_t maxSize = o.eval.limits.maxSize;
    for (auto [name, size] : {std::pair{"--width", o.width}, {"--height", o.height}}) {
        if (static_cast<uint32_t>(size) > maxSize)
            return fmt::format("{} {} is above the image size limit {} (raise it with --max-size)", name,
                               size, maxSize);
    }
    return "";
}

} // namespace

ParsedOptions parseOptions(int argc, char** argv) {
    Options o;
    ParsedOptions result;
    auto bad = [&](const std::string& message) {
        result.message = fmt::format("crtc: {}\nTry 'crtc --help'.", message);
        result.status = 2;
        return result;
    };
    for (Arguments args(argc, argv); !args.done();) {
        const std::string_view arg = args.next();
        if (arg == "-h" || arg == "--help") {
            result.message = usage();
            return result;
        }
        if (arg == "--version") {
            result.message = fmt::format("crtc {}", CRT_VERSION);
            return result;
        }
        if (modeOption(arg, args, o) || renderOption(arg, args, o) || previewOption(arg, args, o) ||
            evalOption(arg, args, o)) {
            if (!args.error.empty()) return bad(args.error);
        } else if (arg.size() > 1 && arg[0] == '-') {
            return bad(fmt::format("unknown option '{}'", arg));
        } else if (o.script.empty()) {
            o.script = arg;
        } else {
            return bad(fmt::format("only one script can be given ('{}' and '{}')", o.script, arg));
        }
    }
    if (std::string problem = checkCombination(o); !problem.empty()) return bad(problem);
    result.options = std::move(o);
    return result;
}

} // namespace crt::crtc
