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
  --color WHEN         colour diagnostics: auto, always or never (default auto)
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

} // namespace

ParsedOptions parseOptions(int argc, char** argv) {
    Options o;
    ParsedOptions result;
    auto bad = [&](std::string message) {
        result.options.reset();
        result.message = fmt::format("crtc: {}\nTry 'crtc --help'.", message);
        result.status = 2;
        return result;
    };
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        auto value = [&](std::string_view& out) {
            if (i + 1 >= argc) return false;
            out = argv[++i];
            return true;
        };
        std::string_view v;
        if (arg == "-h" || arg == "--help") {
            result.message = usage();
            return result;
        } else if (arg == "--version") {
            result.message = fmt::format("crtc {}", CRT_VERSION);
            return result;
        } else if (arg == "--check") {
            o.mode = Mode::Check;
        } else if (arg == "--dump-ast") {
            o.mode = Mode::DumpAst;
        } else if (arg == "--dump-scene") {
            o.mode = Mode::DumpScene;
        } else if (arg == "--format") {
            o.mode = Mode::Format;
        } else if (arg == "-Werror") {
            o.werror = true;
        } else if (arg == "-q" || arg == "--quiet") {
            o.quiet = true;
        } else if (arg == "-o") {
            if (!value(v)) return bad("-o needs a file name");
            o.output = v;
        } else if (arg.starts_with("-I")) {
            if (arg.size() > 2) {
                o.eval.includes.dirs.emplace_back(arg.substr(2));
            } else {
                if (!value(v)) return bad("-I needs a folder");
                o.eval.includes.dirs.emplace_back(v);
            }
        } else if (arg == "--assets") {
            if (!value(v)) return bad("--assets needs a folder");
            o.eval.assetRoots.emplace_back(v);
        } else if (arg == "--time") {
            double t = 0;
            if (!value(v) || !parseNumber(v, t)) return bad("--time needs a number");
            o.eval.time = t;
        } else if (arg == "--frames") {
            if (!value(v) || !parseNumber(v, o.frames) || o.frames < 1) return bad("--frames needs a positive integer");
        } else if (arg == "--width" || arg == "--height") {
            int& size = arg == "--width" ? o.width : o.height;
            if (!value(v) || !parseNumber(v, size) || size < 1) return bad(fmt::format("{} needs a positive integer", arg));
        } else if (arg == "--threads") {
            if (!value(v) || !parseNumber(v, o.threads) || o.threads < 1) return bad("--threads needs a positive integer");
        } else if (arg == "--fps") {
            if (!value(v) || !parseNumber(v, o.fps) || !(o.fps > 0) || o.fps > 100) return bad("--fps needs a number in (0, 100]");
        } else if (arg == "--png-compression") {
            if (!value(v) || !parseNumber(v, o.pngCompression) || o.pngCompression < 0 || o.pngCompression > 9) return bad("--png-compression needs an integer from 0 to 9");
        } else if (arg == "--stats") {
            o.stats = true;
        } else if (arg == "--seed") {
            if (!value(v) || !parseNumber(v, o.eval.seed)) return bad("--seed needs a non-negative integer");
        } else if (arg == "--max-steps") {
            if (!value(v) || !parseNumber(v, o.eval.limits.maxSteps)) return bad("--max-steps needs a non-negative integer");
        } else if (arg == "--max-depth") {
            if (!value(v) || !parseNumber(v, o.eval.limits.maxDepth)) return bad("--max-depth needs a non-negative integer");
            // Each nested call takes about 2 KB of the front end's 1 GB stack.
            if (o.eval.limits.maxDepth > kMaxSupportedDepth) {
                return bad(fmt::format("--max-depth above {} is not supported", kMaxSupportedDepth));
            }
        } else if (arg == "--max-entities") {
            if (!value(v) || !parseNumber(v, o.eval.limits.maxEntities)) return bad("--max-entities needs a non-negative integer");
        } else if (arg == "--max-size") {
            if (!value(v) || !parseNumber(v, o.eval.limits.maxSize) || o.eval.limits.maxSize == 0) {
                return bad("--max-size needs a positive integer");
            }
        } else if (arg == "--color" || arg.starts_with("--color=")) {
            if (arg == "--color") {
                if (!value(v)) return bad("--color needs auto, always or never");
            } else {
                v = arg.substr(8);
            }
            if (v == "auto") o.colour = ColourWhen::Auto;
            else if (v == "always") o.colour = ColourWhen::Always;
            else if (v == "never") o.colour = ColourWhen::Never;
            else return bad(fmt::format("--color takes auto, always or never, not '{}'", v));
        } else if (arg.size() > 1 && arg[0] == '-') {
            return bad(fmt::format("unknown option '{}'", arg));
        } else if (o.script.empty()) {
            o.script = arg;
        } else {
            return bad(fmt::format("only one script can be given ('{}' and '{}')", o.script, arg));
        }
    }
    if (o.script.empty()) return bad("no script given");
    if (o.frames > 0 && o.eval.time) return bad("--time and --frames cannot be combined");
    result.options = std::move(o);
    return result;
}

} // namespace crt::crtc
