// crtc: checks, dumps and renders CRT scene scripts.
#include "ast_dump.hpp"
#include "diagnostic_printer.hpp"
#include "formatter.hpp"
#include "interpreter.hpp"
#include "large_stack.hpp"
#include "options.hpp"
#include "preview_launch.hpp"
#include "render_command.hpp"
#include "render_cost.hpp"
#include "scene/quality_overrides.hpp"
#include "scene/scene_json.hpp"
#include "stop_signals.hpp"
#include "terminal_text.hpp"
#include "tracer/image_io/temporary_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace crt;
using namespace crt::lang;

namespace {

bool useColor(crtc::ColorWhen when) {
    if (when == crtc::ColorWhen::Always) return true;
    if (when == crtc::ColorWhen::Never) return false;
    const char* term = std::getenv("TERM");
    return isatty(STDERR_FILENO) && !std::getenv("NO_COLOR") && term && std::string_view(term) != "dumb";
}

/// Why the file at `path` could not be read: missing, a folder, not permitted.
std::string whyUnreadable(const std::string& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (status.type() == fs::file_type::not_found) return "no such file";
    if (status.type() == fs::file_type::directory) return "it is a folder";
    std::ifstream probe(path);
    if (!probe) return std::strerror(errno);
    return "it is not a regular file";
}

/// Prints the diagnostics of one compilation, except those already printed for an
/// earlier frame; returns whether it had errors.
bool report(Compilation& c, const crtc::Options& options, std::set<std::string>& printed) {
    if (options.werror) c.diagnostics.promoteWarnings();
    PrintOptions print;
    print.color = useColor(options.color);
    // As compilers do: past --max-errors errors the rest is noise (a binary file given as a
    // script makes millions), so reporting stops there.
    size_t errors = 0;
    for (const Diagnostic& diagnostic : c.diagnostics.items()) {
        const bool isError = diagnostic.severity == Severity::Error;
        if (isError && options.maxErrors != 0 && errors == options.maxErrors) {
            std::cerr << "crtc: too many errors (" << c.diagnostics.errorCount()
                      << "); stopping after " << options.maxErrors << " (--max-errors)\n";
            break;
        }
        std::string text = formatDiagnostic(c.sources, diagnostic, print);
        if (printed.insert(text).second) {
            std::cerr << text;
            errors += isError ? 1 : 0;
        }
    }
    return c.diagnostics.hasErrors();
}

/// Warns (once, as report() prints) when the render the scene and the command line ask for
/// is estimated beyond any reasonable time.
void warnAboutCost(const scene::SceneDesc& evaluated, const crtc::Options& options, std::set<std::string>& printed) {
    scene::SceneDesc asRendered; // what the estimate reads, with the command line's overrides
    asRendered.settings = evaluated.settings;
    asRendered.camera = evaluated.camera;
    asRendered.lights = evaluated.lights;
    asRendered.finishes = evaluated.finishes;
    scene::applyQuality(asRendered, options.quality);
    if (options.width > 0) asRendered.settings.width = options.width;
    if (options.height > 0) asRendered.settings.height = options.height;
    if (std::optional<std::string> warning = crtc::renderCostWarning(asRendered)) {
        if (printed.insert(*warning).second) std::cerr << *warning;
    }
}

/// crtc --format: the formatted script on standard output or in -o FILE.
int formatCommand(const crtc::Options& options, std::string text) {
    FormatResult result = formatSource(text);
    if (!result.ok) {
        // Show why (the syntax errors) the way --check would.
        Compilation c = compile(options.script, std::move(text), options.eval, false);
        std::set<std::string> printed;
        report(c, options, printed);
        std::cerr << "crtc: not formatted: " << terminalSafe(result.error) << "\n";
        return 1;
    }
    if (options.output.empty()) {
        std::cout << result.text;
        return 0;
    }
    // Written beside the target and renamed, so a failed write never truncates the file.
    std::string error;
    tracer::image_io::TemporaryFile temporary(options.output, error);
    if (temporary.ok()) {
        std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
        out << result.text;
        out.close();
        if (!out) error = "the write failed";
        else if (temporary.commit(error)) return 0;
    }
    std::cerr << "crtc: cannot write '" << terminalSafe(options.output) << "': " << error << "\n";
    return 2;
}

int run(int argc, char** argv) {
    crtc::ParsedOptions parsed = crtc::parseOptions(argc, argv);
    if (!parsed.options) {
        (parsed.status == 0 ? std::cout : std::cerr) << parsed.message << (parsed.message.ends_with('\n') ? "" : "\n");
        return parsed.status;
    }
    crtc::Options& options = *parsed.options;
    crtc::installStopHandlers();
    crtc::installExitCleanup();
    options.eval.includes.stdlibDir = defaultStdlibDir();

    std::optional<std::string> text = readFile(options.script);
    if (!text) {
        std::cerr << "crtc: cannot read '" << terminalSafe(options.script) << "': " << whyUnreadable(options.script)
                  << "\n";
        return 2;
    }

    if (options.mode == crtc::Mode::Format) return formatCommand(options, std::move(*text));
    if (options.mode == crtc::Mode::Preview) return crtc::launchPreview(argv);

    // The dumps own standard output: print() goes to standard error beside them.
    if (options.mode == crtc::Mode::DumpAst || options.mode == crtc::Mode::DumpScene) {
        options.eval.printOut = &std::cerr;
    }
    options.eval.escapePrint = isatty(options.eval.printOut ? STDERR_FILENO : STDOUT_FILENO);
    if (options.mode == crtc::Mode::DumpAst) {
        Compilation c = compile(options.script, std::move(*text), options.eval, false);
        std::string dump;
        runOnLargeStack([&] { dump = dumpAst(c.main, c.sources.file(0)); });
        std::cout << dump;
        std::set<std::string> printed;
        return report(c, options, printed) ? 1 : 0;
    }

    const crtc::FrameSelection& frames = options.frames;
    options.eval.frameCount = std::max(frames.count, 1);
    options.eval.firstFrame = frames.first;
    options.eval.clockStart = frames.clockStart;
    options.eval.clockEnd = frames.clockEnd;
    std::set<std::string> printed;
    // The last frame can have the text itself; earlier ones get a copy.
    auto compileFrame = [&](int frame, Compilation& c) {
        options.eval.frame = frame;
        c = compile(options.script, frame + 1 == frames.end() ? std::move(*text) : *text, options.eval);
        if (report(c, options, printed)) {
            if (frames.count > 1) std::cerr << "crtc: frame " << frame << " has errors\n";
            return false;
        }
        if ((options.mode == crtc::Mode::Render || options.mode == crtc::Mode::Check) && c.scene) {
            warnAboutCost(*c.scene, options, printed);
        }
        return true;
    };
    if (options.mode == crtc::Mode::Render) return crtc::renderCommand(options, compileFrame);

    // --dump-scene of an animation prints an array of the frames evaluated.
    const bool array = frames.count > 1;
    std::string json;
    for (int frame = frames.begin(); frame < frames.end(); ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        if (options.mode == crtc::Mode::DumpScene && c.scene) {
            json += array ? (frame == frames.begin() ? "[\n" : ",\n") : "";
            json += scene::sceneToJson(*c.scene);
        }
    }
    if (options.mode == crtc::Mode::DumpScene) std::cout << json << (array ? "]\n" : "");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        // Evaluation reports this at the script's statement; what is left (parsing a huge
        // file, building the scene) ends here rather than in an abort.
        std::cerr << "crtc: out of memory\n";
        return 2;
    }
}
