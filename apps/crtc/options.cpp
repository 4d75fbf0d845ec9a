// Parsing crtc's command line, with CLI11: --opt=value, -- before a script whose name starts
// with '-', generated help, and crtc's own wording of errors.
#include "options.hpp"

#include "diagnostic.hpp"
#include "help_formatter.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>

namespace crt::crtc {

namespace {

template <typename T> bool parseNumber(std::string_view text, T& out) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size();
}

/// The numbers of "A:B:…", exactly `count` of them; false if the text is not that.
template <typename T>
bool parseNumberList(std::string_view text, size_t count, std::vector<T>& out) {
    out.clear();
    for (size_t start = 0;;) {
        const size_t colon = text.find(':', start);
        T value{};
        if (!parseNumber(text.substr(start, colon - start), value)) return false;
        out.push_back(value);
        if (colon == std::string_view::npos) break;
        start = colon + 1;
    }
    return out.size() == count;
}

/// A validator accepting numbers of type T in [lo, hi]; `what` completes "--opt needs ...".
template <typename T> CLI::Validator numberIn(T lo, T hi, std::string what) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            T value{};
            if (parseNumber(text, value) && value >= lo && value <= hi) return "";
            return fmt::format("needs {}, not '{}'", what, text);
        },
        "");
}

CLI::Validator positiveInt() {
    return numberIn<int>(1, std::numeric_limits<int>::max(), "a positive integer");
}

template <typename T> CLI::Validator anyNumber(std::string what) {
    return numberIn<T>(std::numeric_limits<T>::lowest(), std::numeric_limits<T>::max(),
                       std::move(what));
}

CLI::Validator sampleCount(scene::CountRange range) {
    return numberIn<int>(range.min, range.max,
                         fmt::format("an integer from {} to {}", range.min, range.max));
}

/// A validator for one of `names`.
CLI::Validator oneOf(std::vector<std::string> names) {
    return CLI::Validator(
        [names](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return "";
            std::string list;
            for (size_t i = 0; i < names.size(); ++i)
                list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
            return fmt::format("takes {}, not '{}'", list, text);
        },
        "");
}

void addModeOptions(CLI::App& app, Options& o) {
    const char* group = "Modes (default: render)";
    auto mode = [&](const char* name, Mode m, const char* help) {
        return app
            .add_flag_callback(
                name, [&o, m] { o.mode = m; }, help)
            ->group(group);
    };
    CLI::Option* check = mode("--check", Mode::Check, "report diagnostics only");
    CLI::Option* ast = mode("--dump-ast", Mode::DumpAst, "print the syntax tree");
    CLI::Option* dump = mode("--dump-scene", Mode::DumpScene,
                             "print the evaluated scene as JSON (docs/scene-json.md)");
    CLI::Option* format = mode("--format", Mode::Format,
                               "print the script formatted (to -o FILE if given); a script with "
                               "syntax errors is refused");
    CLI::Option* preview = mode("--preview", Mode::Preview,
                                "serve a live preview with a mouse-driven camera on 127.0.0.1 and print its URL "
                                "(docs/preview.md)");
    const std::vector<CLI::Option*> modes{check, ast, dump, format, preview};
    for (CLI::Option* a : modes)
        for (CLI::Option* b : modes)
            if (a != b) a->excludes(b);
}

void addOutputOptions(CLI::App& app, Options& o) {
    const char* group = "Output";
    app.add_option("-o,--output", o.output,
                   "output image (default: the script's name with .png, or .gif with --frames); "
                   "the extension picks the format: .png .jpg .tif .exr .hdr .gif; with --frames, "
                   "a name with %d or %04d writes numbered images instead of an animated GIF")
        ->type_name("FILE")
        ->group(group);
    app.add_option("--width", o.width, "override the script's image width")
        ->check(positiveInt())
        ->type_name("N")
        ->group(group);
    app.add_option("--height", o.height, "override the script's image height")
        ->check(positiveInt())
        ->type_name("N")
        ->group(group);
    app.add_option("--region",
                   "render only columns X0..X1-1 of rows Y0..Y1-1, into an image of that size")
        ->type_name("X0:Y0:X1:Y1")
        ->group(group)
        ->check(CLI::Validator(
            [&o](std::string& text) -> std::string {
                std::vector<int> v;
                if (!parseNumberList(text, 4, v) || v[0] < 0 || v[1] < 0 || v[2] <= v[0] ||
                    v[3] <= v[1])
                    return fmt::format(
                        "needs X0:Y0:X1:Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, not '{}'", text);
                o.region = tracer::Tile{v[0], v[1], v[2], v[3]};
                return "";
            },
            ""));
    app.add_flag("--alpha", o.alpha,
                 "write an alpha channel, the background transparent (.png, .tif, .exr)")
        ->group(group);
    app.add_option("--png-compression", o.pngCompression,
                   "zlib level of PNG output, 0 (fastest) to 9 (smallest); default 2")
        ->check(numberIn(0, 9, "an integer from 0 to 9"))
        ->type_name("N")
        ->group(group);
    app.add_flag("--continue", o.resume,
                 "finish an interrupted render of the same output, rendering only what it had not done")
        ->group(group);
    app.add_option("--resume-log-after", o.resumeLogAfter,
                   "log the tiles --continue reuses once a frame has rendered S seconds "
                   "(default 5; 0: from the start)")
        ->check(numberIn(0.0, 1e6, "a number of seconds from 0 to 1000000"))
        ->type_name("S")
        ->group(group);
    app.add_option("--fps", o.fps, "frames per second of an animated GIF (default 15)")
        ->check(numberIn(1e-3, 100.0, "a number from 0.001 to 100"))
        ->type_name("F")
        ->group(group);
}

void addPreviewOptions(CLI::App& app, Options& o) {
    const char* group = "Preview";
    app.add_option("--port", o.port, "--preview: listen on port N (default 0: a free port)")
        ->check(numberIn(0, 65535, "a port number from 0 (a free port) to 65535"))
        ->type_name("N")
        ->group(group);
    app.add_flag("--open", o.open, "--preview: open the URL with xdg-open")->group(group);
}

void addQualityOptions(CLI::App& app, Options& o) {
    const char* group = "Quality (overrides the script's Settings)";
    scene::QualityOverrides& q = o.quality;
    app.add_flag("--draft", q.draft,
                 "one sample a pixel, no depth of field, one shadow and glossy ray")
        ->group(group);
    app.add_option("--supersampling", q.supersampling, "an N x N grid of camera samples a pixel")
        ->check(sampleCount(scene::kSupersamplingRange))
        ->type_name("N")
        ->group(group);
    app.add_option("--antialias", "grid, adaptive, showadaptive or stratified")
        ->type_name("MODE")
        ->group(group)
        ->check(oneOf({scene::kAntialiasNames[0].data(), scene::kAntialiasNames[1].data(),
                       scene::kAntialiasNames[2].data(), scene::kAntialiasNames[3].data()}))
        ->each([&q](const std::string& name) {
            for (size_t i = 0; i < std::size(scene::kAntialiasNames); ++i)
                if (name == scene::kAntialiasNames[i])
                    q.antialias = static_cast<scene::Antialias>(i);
        });
    app.add_option("--integrator", "whitted or path (path tracing: light bounces off every surface)")
        ->type_name("NAME")
        ->group(group)
        ->check(oneOf({scene::kIntegratorNames[0].data(), scene::kIntegratorNames[1].data()}))
        ->each([&q](const std::string& name) {
            for (size_t i = 0; i < std::size(scene::kIntegratorNames); ++i)
                if (name == scene::kIntegratorNames[i]) q.integrator = static_cast<scene::Integrator>(i);
        });
    app.add_option("--samples", q.samples, "paths a pixel (the path integrator's)")
        ->check(sampleCount(scene::kPathSamplesRange))
        ->type_name("N")
        ->group(group);
    app.add_option("--target-error", q.targetError,
                   "path: a pixel stops taking paths once the relative standard error of its mean is "
                   "below E (--samples is then the most it takes)")
        ->check(numberIn<double>(std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                                 "a number above 0"))
        ->type_name("E")
        ->group(group);
    app.add_option("--time-limit", o.timeLimit,
                   "path: a frame stops at S seconds (its scene build included) with the image so far; "
                   "pixels take paths in passes over the image until then")
        ->check(numberIn(1e-3, 1e9, "a number of seconds from 0.001 to 1000000000"))
        ->type_name("S")
        ->group(group);
    app.add_option("--aov", "path: also write each pixel's variance, and the albedo and normal of what its "
                            "paths first meet, as IMAGE.variance.exr and so on (a comma-separated LIST)")
        ->type_name("LIST")
        ->group(group)
        ->check(CLI::Validator(
            [&o](std::string& text) -> std::string {
                std::string_view rest = text;
                while (true) {
                    const std::string_view name = rest.substr(0, rest.find(','));
                    const auto* found = std::find(tracer::kAovNames.begin(), tracer::kAovNames.end(), name);
                    if (found == tracer::kAovNames.end())
                        return fmt::format("takes a list of variance, albedo and normal, not '{}'", name);
                    o.aovs.add(static_cast<tracer::Aov>(found - tracer::kAovNames.begin()));
                    if (name.size() == rest.size()) return "";
                    rest.remove_prefix(name.size() + 1);
                }
            },
            ""));
    app.add_option("--dofsamples", q.dofSamples, "lens samples a camera sample (depth of field)")
        ->check(sampleCount(scene::kDofSamplesRange))
        ->type_name("N")
        ->group(group);
    app.add_option("--shadowsamples", q.shadowSamples, "samples an area or cylinder light")
        ->check(sampleCount(scene::kShadowSamplesRange))
        ->type_name("N")
        ->group(group);
    app.add_option("--glossysamples", q.glossySamples,
                   "samples a glossy reflection or transmission")
        ->check(sampleCount(scene::kGlossySamplesRange))
        ->type_name("N")
        ->group(group);
    app.add_option("--threads", o.threads, "threads (default: the cores crtc may run on)")
        ->check(positiveInt())
        ->type_name("N")
        ->group(group);
}

/// "A:B" as two numbers of type T, into `out`.
template <typename T> CLI::Validator pairOf(std::pair<T, T>& out, std::string what) {
    return CLI::Validator(
        [&out, what](std::string& text) -> std::string {
            std::vector<T> v;
            if (!parseNumberList(text, 2, v)) return fmt::format("needs {}, not '{}'", what, text);
            out = {v[0], v[1]};
            return "";
        },
        "");
}

void addAnimationOptions(CLI::App& app, Options& o, std::pair<int, int>& range,
                         std::pair<double, double>& clock) {
    const char* group = "Animation";
    FrameSelection& f = o.frames;
    app.add_option("--frames", f.count, "evaluate N frames: t = 0 .. N-1, clock from 0 to 1")
        ->check(positiveInt())
        ->type_name("N")
        ->group(group);
    app.add_option("--frame-range",
                   "render only frames A to B (both included), numbered as in the whole animation")
        ->check(pairOf(range, "two frame numbers A:B"))
        ->type_name("A:B")
        ->group(group);
    app.add_option("--first-frame", f.first,
                   "number the frames K .. K+N-1 (t and file numbers; default 0)")
        ->check(numberIn(0, 1'000'000'000, "an integer from 0 to 1000000000"))
        ->type_name("K")
        ->group(group);
    app.add_option("--clock", "clock at the first and at the last frame (default 0:1)")
        ->check(pairOf(clock, "two numbers A:B"))
        ->type_name("A:B")
        ->group(group);
    app.add_option("--time", "evaluate with t = T (a float); with --frames, render only frame T")
        ->check(anyNumber<double>("a number"))
        ->type_name("T")
        ->group(group)
        ->each([&o](const std::string& text) { o.eval.time = std::stod(text); });
    app.add_option("--shutter",
                   "motion blur: the shutter open from t + A to t + B, instead of the script's "
                   "shutteropen and shutterclose (0:0 closes it)")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                std::vector<double> v;
                if (!parseNumberList(text, 2, v) || !(v[0] <= v[1]))
                    return fmt::format("needs two numbers A:B, A at most B, not '{}'", text);
                return "";
            },
            ""))
        ->type_name("A:B")
        ->group(group)
        ->each([&o](const std::string& text) {
            std::vector<double> v;
            parseNumberList(text, 2, v);
            o.eval.shutter = std::pair{v[0], v[1]};
        });
}

void addEvaluationOptions(CLI::App& app, Options& o) {
    const char* group = "Evaluation";
    lang::EvalOptions& eval = o.eval;
    app.add_option("-I", eval.includes.dirs, "add DIR to the include search path (repeatable)")
        ->allow_extra_args(false)
        ->type_name("DIR")
        ->group(group);
    app.add_option("--assets", eval.assetRoots,
                   "asset root for \"/...\" image and mesh paths (repeatable)")
        ->allow_extra_args(false)
        ->type_name("DIR")
        ->group(group);
    app.add_option("--allow-read", eval.access.allowRead,
                   "let the script read files under DIR too (repeatable); else only its folder, the include "
                   "path and the asset roots")
        ->allow_extra_args(false)
        ->type_name("DIR")
        ->group(group);
    app.add_flag("--allow-read-all", eval.access.allowAll, "let the script read any file")->group(group);
    app.add_option("--seed", eval.seed, "seed of rand() (default 0)")
        ->check(anyNumber<uint64_t>("a non-negative integer"))
        ->type_name("S")
        ->group(group);
    lang::Limits& limits = eval.limits;
    app.add_option("--max-steps", limits.maxSteps,
                   fmt::format("evaluation steps: loop iterations and macro calls (default {})",
                               limits.maxSteps))
        ->check(anyNumber<uint64_t>("a non-negative integer"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-depth", limits.maxDepth,
                   fmt::format("nested macro calls (default {})", limits.maxDepth))
        ->check(numberIn<uint32_t>(0, lang::Limits::kMaxSupportedDepth,
                                   fmt::format("an integer from 0 to {}", lang::Limits::kMaxSupportedDepth)))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-entities", limits.maxEntities,
                   fmt::format("entities built and list length (default {})", limits.maxEntities))
        ->check(anyNumber<uint64_t>("a non-negative integer"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-primitives", limits.render.maxPrimitives,
                   fmt::format("primitives stored after CSG, groups and instancing (default {})",
                               limits.render.maxPrimitives))
        ->check(numberIn<uint64_t>(0, scene::RenderLimits::kMostPrimitives,
                                   fmt::format("an integer from 0 to {}", scene::RenderLimits::kMostPrimitives)))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-image-pixels", limits.render.maxImagePixels,
                   fmt::format("pixels of an image read (default {})", limits.render.maxImagePixels))
        ->check(anyNumber<uint64_t>("a non-negative integer"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-isosurface-evaluations", limits.render.maxIsosurfaceEvaluations,
                   fmt::format("evaluations of an isosurface's function along one line (default {})",
                               limits.render.maxIsosurfaceEvaluations))
        ->check(numberIn<uint64_t>(1, uint64_t{1} << 40, "an integer from 1 to 1099511627776"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-mesh-size", limits.maxMeshSize,
                   fmt::format("vertices or triangles of one mesh file (default {})",
                               limits.maxMeshSize))
        ->check(numberIn<uint64_t>(1, uint64_t{1} << 31, "an integer from 1 to 2147483648"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-text-length", limits.maxTextLength,
                   fmt::format("characters of one Text (default {})", limits.maxTextLength))
        ->check(numberIn<uint64_t>(1, uint64_t{1} << 31, "an integer from 1 to 2147483648"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-size", limits.maxSize,
                   fmt::format("image width and height (default {})", limits.maxSize))
        ->check(numberIn<uint32_t>(1, std::numeric_limits<uint32_t>::max(), "a positive integer"))
        ->type_name("N")
        ->group(group);
    app.add_option("--max-memory")
        ->description(fmt::format("MiB for strings, lists, objects (default {})",
                                  limits.maxMemory >> 20))
        ->check(numberIn<uint64_t>(1, uint64_t{1} << 40, "an integer from 1 to 1099511627776"))
        ->type_name("MIB")
        ->group(group)
        ->each([&limits](const std::string& text) { limits.maxMemory = std::stoull(text) << 20; });
}

void addReportingOptions(CLI::App& app, Options& o) {
    const char* group = "Reporting";
    app.add_flag("--werror", o.werror, "treat warnings as errors (also -Werror)")->group(group);
    app.add_option("--max-errors", o.maxErrors,
                   fmt::format("errors shown before stopping, 0: all (default {})", o.maxErrors))
        ->check(anyNumber<uint32_t>("a non-negative integer"))
        ->type_name("N")
        ->group(group);
    app.add_option("--color", "color diagnostics: auto, always or never (default auto)")
        ->type_name("WHEN")
        ->group(group)
        ->check(oneOf({"auto", "always", "never"}))
        ->each([&o](const std::string& when) {
            o.color = when == "always"  ? ColorWhen::Always
                      : when == "never" ? ColorWhen::Never
                                        : ColorWhen::Auto;
        });
    app.add_flag("-q,--quiet", o.quiet, "print nothing but diagnostics (no progress, no summary)")
        ->group(group);
    app.add_flag("--stats", o.stats, "print ray and acceleration-structure counts after rendering")
        ->group(group);
}

/// The long names of `app`'s options, for did-you-mean.
std::vector<std::string> longNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options())
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    return names;
}

/// For a POV-Ray command-line option (`+W320`, `+A0.3`), how crtc says it; "" for anything else.
std::string povRayOptionProblem(const std::string& arg) {
    if (arg.size() < 2 || arg[0] != '+' || !std::isupper(static_cast<unsigned char>(arg[1])))
        return "";
    struct Spelling {
        std::string_view pov, crtc;
    };
    // Longest first, so that +WT is not read as +W.
    static constexpr Spelling kOptions[] = {
        {"WT", "--threads N"},
        {"KFF", "--frames N"},
        {"SF", "--frame-range A:B"},
        {"EF", "--frame-range A:B"},
        {"UA", "--alpha"},
        {"W", "--width N"},
        {"H", "--height N"},
        {"O", "-o FILE"},
        {"A", "Settings.antialias -> \"adaptive\" and aathreshold"},
        {"R", "Settings.aadepth"},
        {"L", "-I DIR"},
        {"I", "the script's name alone"},
    };
    const std::string_view name = std::string_view(arg).substr(1);
    for (const Spelling& option : kOptions)
        if (name.starts_with(option.pov))
            return fmt::format("'{}' is a POV-Ray option; crtc's is {}", arg, option.crtc);
    return fmt::format("'{}' is a POV-Ray option; crtc's options start with '-' (crtc --help)",
                       arg);
}

/// What CLI11 left over: an unknown option or a second script, as a message ("" if none).
std::string leftOverProblem(const CLI::App& app, const Options& o) {
    if (std::string problem = povRayOptionProblem(o.script); !problem.empty()) return problem;
    bool afterDashes = false;
    for (const std::string& arg : app.remaining()) {
        if (std::string problem = povRayOptionProblem(arg); !afterDashes && !problem.empty())
            return problem;
        if (!afterDashes && arg == "--") {
            afterDashes = true;
            continue;
        }
        if (!afterDashes && arg.size() > 1 && arg[0] == '-') {
            const std::vector<std::string> names = longNames(app);
            const std::string_view option = std::string_view(arg).substr(0, arg.find('='));
            const std::string suggestion = lang::closestMatch(option, {names.begin(), names.end()});
            return fmt::format(
                "unknown option '{}'{}", option,
                suggestion.empty() ? "" : fmt::format("; did you mean '{}'?", suggestion));
        }
        return fmt::format("only one script can be given ('{}' and '{}')", o.script, arg);
    }
    return "";
}

/// What no single option can check; also turns --time with --frames into a frame range.
std::string checkCombination(Options& o, const std::optional<std::pair<int, int>>& range) {
    if (o.script.empty()) return "no script given";
    FrameSelection& f = o.frames;
    if (!f.animated() && (range || f.first != 0))
        return "--frame-range and --first-frame need --frames";
    if (range) f.range = range;
    if (f.animated() && o.eval.time) {
        const double t = *o.eval.time;
        if (range) return "--time and --frame-range cannot be combined";
        if (t != static_cast<int>(t))
            return fmt::format("with --frames, --time needs a frame number, not {}", t);
        f.range = std::pair{static_cast<int>(t), static_cast<int>(t)};
        o.eval.time.reset();
    }
    if (f.range && (f.range->first > f.range->second || f.range->first < f.first ||
                    f.range->second > f.last()))
        return fmt::format("frames {} to {} are not within the animation's frames {} to {}",
                           f.range->first, f.range->second, f.first, f.last());
    const uint32_t maxSize = o.eval.limits.maxSize;
    for (auto [name, size] : {std::pair{"--width", o.width}, {"--height", o.height}}) {
        if (static_cast<uint32_t>(size) > maxSize)
            return fmt::format("{} {} is above the image size limit {} (raise it with --max-size)",
                               name, size, maxSize);
    }
    return "";
}

/// CLI11's "--opt: message" as crtc words it: "--opt message".
std::string crtcWording(const CLI::ParseError& e) {
    std::string text = e.what();
    const size_t colon = text.find(": ");
    if (text.starts_with('-') && colon != std::string::npos && text.find(' ') > colon)
        text.replace(colon, 2, " ");
    return text;
}

/// argv, with GCC's spelling -Werror taken as --werror, in the reversed order CLI11 parses.
std::vector<std::string> reversedArguments(int argc, char** argv) {
    std::vector<std::string> args;
    bool afterDashes = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        afterDashes = afterDashes || arg == "--";
        args.push_back(!afterDashes && arg == "-Werror" ? "--werror" : arg);
    }
    std::reverse(args.begin(), args.end());
    return args;
}

} // namespace

ParsedOptions parseOptions(int argc, char** argv) {
    Options o;
    ParsedOptions result;
    CLI::App app("Evaluates a CRT scene script and renders it.", "crtc");
    app.formatter(std::make_shared<HelpFormatter>());
    app.footer("exit status: 0 success, 1 errors in the script, 2 bad usage or I/O failure,\n"
               "             128+N stopped by signal N (Ctrl-C 130, SIGTERM 143; no partial\n"
               "             image or temporary file is left)");
    app.set_version_flag("--version", fmt::format("crtc {}", CRT_VERSION));
    app.allow_extras();
    app.add_option("script", o.script, "the CRT script")->type_name("SCRIPT");
    std::pair<int, int> range{0, 0};
    std::pair<double, double> clock{0.0, 1.0};
    addModeOptions(app, o);
    addOutputOptions(app, o);
    addQualityOptions(app, o);
    addPreviewOptions(app, o);
    addAnimationOptions(app, o, range, clock);
    addEvaluationOptions(app, o);
    addReportingOptions(app, o);
    auto bad = [&](const std::string& message) {
        result.message = fmt::format("crtc: {}\nTry 'crtc --help'.", message);
        result.status = 2;
        return result;
    };
    try {
        std::vector<std::string> args = reversedArguments(argc, argv);
        app.parse(args);
    } catch (const CLI::CallForHelp&) {
        result.message = app.help();
        return result;
    } catch (const CLI::CallForVersion& e) {
        result.message = e.what();
        return result;
    } catch (const CLI::ParseError& e) {
        return bad(crtcWording(e));
    }
    if (std::string problem = leftOverProblem(app, o); !problem.empty()) return bad(problem);
    if ((o.port != 0 || o.open) && o.mode != Mode::Preview) return bad("--port and --open need --preview");
    o.frames.clockStart = clock.first;
    o.frames.clockEnd = clock.second;
    const bool rangeGiven = app.count("--frame-range") > 0;
    if (std::string problem = checkCombination(o, rangeGiven ? std::optional(range) : std::nullopt);
        !problem.empty())
        return bad(problem);
    result.options = std::move(o);
    return result;
}

tracer::RenderJob renderJob(const Options& options) {
    tracer::RenderJob job;
    job.threads = options.threads;
    job.alpha = options.alpha;
    job.aovs = options.aovs;
    if (options.timeLimit > 0) {
        const auto limit = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(options.timeLimit));
        job.progressive = tracer::ProgressiveRender{std::chrono::steady_clock::now() + limit, {}};
    }
    return job;
}

} // namespace crt::crtc
