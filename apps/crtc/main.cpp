// crtc: checks, dumps and renders CRT scene scripts.
#include "ast_dump.hpp"
#include "diagnostic_printer.hpp"
#include "formatter.hpp"
#include "interpreter.hpp"
#include "large_stack.hpp"
#include "options.hpp"
#include "preview/preview_command.hpp"
#include "render_command.hpp"
#include "scene/scene_json.hpp"

#include <algorithm>
#include <cstdio>
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

/// Prints the diagnostics of one compilation, except those already printed for an
/// earlier frame; returns whether it had errors.
bool report(Compilation& c, const crtc::Options& options, std::set<std::string>& printed) {
    if (options.werror) c.diagnostics.promoteWarnings();
    PrintOptions print;
    print.color = useColor(options.color);
    for (const Diagnostic& diagnostic : c.diagnostics.items()) {
        std::string text = formatDiagnostic(c.sources, diagnostic, print);
        if (printed.insert(text).second) std::cerr << text;
    }
    return c.diagnostics.hasErrors();
}

/// crtc --format: the formatted script on standard output or in -o FILE.
int formatCommand(const crtc::Options& options, std::string text) {
    FormatResult result = formatSource(text);
    if (!result.ok) {
        // Show why (the syntax errors) the way --check would.
        Compilation c = compile(options.script, std::move(text), options.eval, false);
        std::set<std::string> printed;
        report(c, options, printed);
        std::cerr << "crtc: not formatted: " << result.error << "\n";
        return 1;
    }
    if (options.output.empty()) {
        std::cout << result.text;
        return 0;
    }
    // Write beside the target and rename, so a failed write never truncates the file.
    std::string temporary = options.output + ".crtc-format.tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << result.text;
        if (!out.flush()) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            std::cerr << "crtc: cannot write '" << options.output << "'\n";
            return 2;
        }
    }
    std::error_code error;
    fs::rename(temporary, options.output, error);
    if (error) {
        fs::remove(temporary, error);
        std::cerr << "crtc: cannot write '" << options.output << "'\n";
        return 2;
    }
    return 0;
}

int run(int argc, char** argv) {
    crtc::ParsedOptions parsed = crtc::parseOptions(argc, argv);
    if (!parsed.options) {
        (parsed.status == 0 ? std::cout : std::cerr) << parsed.message << (parsed.message.ends_with('\n') ? "" : "\n");
        return parsed.status;
    }
    crtc::Options& options = *parsed.options;
    options.eval.includes.stdlibDir = defaultStdlibDir();

    std::optional<std::string> text = readFile(options.script);
    if (!text) {
        std::cerr << "crtc: cannot read '" << options.script << "'\n";
        return 2;
    }

    if (options.mode == crtc::Mode::Format) return formatCommand(options, std::move(*text));
    if (options.mode == crtc::Mode::Preview) return crtc::previewCommand(options);

    // The dumps own standard output: print() goes to standard error beside them.
    if (options.mode == crtc::Mode::DumpAst || options.mode == crtc::Mode::DumpScene) {
        options.eval.printOut = &std::cerr;
    }
    if (options.mode == crtc::Mode::DumpAst) {
        Compilation c = compile(options.script, std::move(*text), options.eval, false);
        std::string dump;
        runOnLargeStack([&] { dump = dumpAst(c.main, c.sources.file(0)); });
        std::cout << dump;
        std::set<std::string> printed;
        return report(c, options, printed) ? 1 : 0;
    }

    int frames = std::max(options.frames, 1);
    options.eval.frameCount = frames;
    std::set<std::string> printed;
    // The last frame can have the text itself; earlier ones get a copy.
    auto compileFrame = [&](int frame, Compilation& c) {
        options.eval.frame = frame;
        c = compile(options.script, frame + 1 == frames ? std::move(*text) : *text, options.eval);
        if (report(c, options, printed)) {
            if (frames > 1) std::cerr << "crtc: frame " << frame << " has errors\n";
            return false;
        }
        return true;
    };
    if (options.mode == crtc::Mode::Render) return crtc::renderCommand(options, compileFrame);

    std::string json;
    for (int frame = 0; frame < frames; ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        if (options.mode == crtc::Mode::DumpScene && c.scene) {
            json += frames > 1 ? (frame == 0 ? "[\n" : ",\n") : "";
            json += scene::sceneToJson(*c.scene);
        }
    }
    if (options.mode == crtc::Mode::DumpScene) std::cout << json << (frames > 1 ? "]\n" : "");
    return 0;
}

} // namespace

int main(int argc, char** argv) { return run(argc, argv); }
