// crtc: checks, dumps and renders CRT scene scripts.
#include "ast_dump.hpp"
#include "diagnostic_printer.hpp"
#include "formatter.hpp"
#include "huge_page_heap.hpp"
#include "interpreter.hpp"
#include "large_stack.hpp"
#include "options.hpp"
#include "prefaulter.hpp"
#include "render_command.hpp"
#include "scene_json.hpp"
#include "tracer/image_io/image_io.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace crt::lang;

namespace {

// Scripts from this size on get the heap's free top faulted in ahead (driver::Prefaulter), up to
// eight times their size (a script of literal spheres fills about nine), at most this much.
constexpr std::uintmax_t kPrefaultFrom = std::uintmax_t{1} << 20;
constexpr std::uintmax_t kPrefaultAtMost = std::uintmax_t{512} << 20;

/// The standard library next to an installed crtc, else the one in the source tree.
std::string findStdlib(const char* argv0) {
    std::error_code error;
    fs::path exe = fs::canonical("/proc/self/exe", error);
    if (error) exe = fs::absolute(argv0, error);
    fs::path installed = exe.parent_path().parent_path() / "share" / "crt" / "stdlib";
    if (fs::is_directory(installed, error)) return installed.string();
    return CRT_SOURCE_STDLIB_DIR;
}

bool useColour(driver::ColourWhen when) {
    if (when == driver::ColourWhen::Always) return true;
    if (when == driver::ColourWhen::Never) return false;
    const char* term = std::getenv("TERM");
    return isatty(STDERR_FILENO) && !std::getenv("NO_COLOR") && term && std::string_view(term) != "dumb";
}

/// Prints the diagnostics of one compilation, except those already printed for an
/// earlier frame; returns whether it had errors.
bool report(Compilation& c, const driver::Options& options, std::set<std::string>& printed) {
    if (options.werror) c.diagnostics.promoteWarnings();
    PrintOptions print;
    print.colour = useColour(options.colour);
    for (const Diagnostic& diagnostic : c.diagnostics.items()) {
        std::string text = formatDiagnostic(c.sources, diagnostic, print);
        if (printed.insert(text).second) std::cerr << text;
    }
    return c.diagnostics.hasErrors();
}

/// crtc --format: the formatted script on standard output or in -o FILE.
int formatCommand(const driver::Options& options, std::string text) {
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
    driver::ParsedOptions parsed = driver::parseOptions(argc, argv);
    if (!parsed.options) {
        (parsed.status == 0 ? std::cout : std::cerr) << parsed.message << (parsed.message.ends_with('\n') ? "" : "\n");
        return parsed.status;
    }
    driver::Options& options = *parsed.options;
    options.eval.stdlibDir = findStdlib(argv[0]);

    // A second core readies memory the front end is about to fill: for a large script, the
    // heap where its syntax tree will go; in a loop, the room reserved for its objects.
    crt::driver::Prefaulter prefaulter;
    std::error_code sizeError;
    const std::uintmax_t scriptSize = fs::file_size(options.script, sizeError);
    if (!sizeError && scriptSize >= kPrefaultFrom)
        prefaulter.addHeapTop(std::min<std::uintmax_t>(scriptSize * 8, kPrefaultAtMost));
    options.eval.readyMemory = [&prefaulter](void* begin, size_t bytes) {
        prefaulter.add(begin, bytes);
    };

    std::optional<std::string> text = readFile(options.script);
    if (!text) {
        std::cerr << "crtc: cannot read '" << options.script << "'\n";
        return 2;
    }

    if (options.mode == driver::Mode::Format) return formatCommand(options, std::move(*text));

    // The dumps own standard output: print() goes to standard error beside them.
    if (options.mode == driver::Mode::DumpAst || options.mode == driver::Mode::DumpScene) {
        options.eval.printOut = &std::cerr;
    }
    if (options.mode == driver::Mode::DumpAst) {
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
    if (options.mode == driver::Mode::Render) return driver::renderCommand(options, compileFrame);

    std::string json;
    for (int frame = 0; frame < frames; ++frame) {
        Compilation c;
        if (!compileFrame(frame, c)) return 1;
        if (options.mode == driver::Mode::DumpScene && c.scene) {
            json += frames > 1 ? (frame == 0 ? "[\n" : ",\n") : "";
            json += sceneToJson(*c.scene);
        }
    }
    if (options.mode == driver::Mode::DumpScene) std::cout << json << (frames > 1 ? "]\n" : "");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    crt::driver::useHugePageHeap();
    int status = run(argc, argv);
    // Never exit while the image module is still being loaded: its libraries' constructors
    // would run alongside the exit handlers (seen as aborts inside dlopen on Ctrl-C).
    if (!crt::tracer::image_io::finishLoading()) return status;
#if defined(__SANITIZE_ADDRESS__)
    return status; // sanitizer builds exit normally, so that LeakSanitizer checks renders too
#endif
    // With OpenImageIO loaded, a normal exit runs the exit handlers and destructors of its
    // ~260 libraries: 30 to 60 ms spent after the image is written. Everything crtc writes is
    // complete by now (the image renamed into place, temporary files removed), so flush the
    // standard streams and leave without them.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    _exit(status);
}
