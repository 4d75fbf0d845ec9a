// Runs one golden language test: a .crt file whose comments state what it must print and
// which diagnostics it must produce, optionally with a --dump-scene snapshot beside it.
//
//   -- expect: TEXT            a line print() must write, in order
//   -- error: LINE:COL TEXT    an error at LINE:COL with message TEXT
//   -- warning: LINE:COL TEXT  a warning
//   -- note: LINE:COL TEXT     a note attached to the diagnostic listed just before
//   -- args: OPTIONS           crtc options for this test (--max-steps, --time, --frames ...)
//   NAME.scene.json            the expected --dump-scene output
//
// Most tests draw without lights, which warns; that warning is compared only in the tests
// that expect it (one of their expected diagnostics says "no lights").
//
// So that expectations do not depend on where the checkout lives, diagnostic messages are
// compared after replacing the absolute path of ROOT with <golden> and that of the standard
// library with <stdlib> (so are --dump-scene snapshots); a line break inside a message is
// written \n. CRT_PATH is ignored.
//
// Usage: golden_runner ROOT FILE.crt [--update]
#include "diagnostic_printer.hpp"
#include "interpreter.hpp"
#include "options.hpp"
#include "scene/scene_json.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace crt;
using namespace crt::lang;

namespace {

std::string readText(const fs::path& path) { return readFile(path.string()).value_or(""); }

struct Expectations {
    std::vector<std::string> printed;
    std::vector<std::string> diagnostics; ///< "error 3:7 message", notes as "  note 3:7 message"
    std::vector<std::string> args;
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

Expectations readExpectations(const std::string& text) {
    Expectations e;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        size_t comment = line.find("-- ");
        if (comment == std::string::npos) continue;
        std::string_view rest = std::string_view(line).substr(comment + 3);
        for (std::string_view kind : {"expect:", "error:", "warning:", "note:", "args:"}) {
            if (!rest.starts_with(kind)) continue;
            std::string_view body = kind == "expect:" ? rest.substr(kind.size()) : trim(rest.substr(kind.size()));
            if (kind == "expect:") {
                if (!body.empty() && body.front() == ' ') body.remove_prefix(1);
                e.printed.emplace_back(trim(body));
            } else if (kind == "args:") {
                std::istringstream words{std::string(body)};
                for (std::string word; words >> word;) e.args.push_back(word);
            } else {
                std::string severity(kind.substr(0, kind.size() - 1));
                e.diagnostics.push_back((severity == "note" ? "  " : "") + severity + " " + std::string(body));
            }
        }
    }
    return e;
}

using PathPlaceholders = std::vector<std::pair<std::string, std::string>>;

/// `text` with machine-specific paths replaced by placeholders.
std::string replacePaths(std::string text, const PathPlaceholders& paths) {
    for (const auto& [path, placeholder] : paths) {
        for (size_t at = text.find(path); at != std::string::npos; at = text.find(path, at + placeholder.size())) {
            text.replace(at, path.size(), placeholder);
        }
    }
    return text;
}

/// `message` with machine-specific paths replaced and line breaks written as \n.
std::string portable(std::string message, const PathPlaceholders& paths) {
    message = replacePaths(std::move(message), paths);
    for (size_t at = message.find('\n'); at != std::string::npos; at = message.find('\n', at + 2)) {
        message.replace(at, 1, "\\n");
    }
    return message;
}

std::vector<std::string> describe(const Compilation& c, const PathPlaceholders& paths,
                                  bool withNoLights) {
    std::vector<std::string> out;
    auto where = [&](SourceRange range) {
        if (range.file >= c.sources.fileCount()) return std::string("?");
        LineColumn at = c.sources.file(range.file).lineColumn(range.begin);
        // Positions in other files (includes) carry the file name.
        std::string prefix = range.file == 0 ? "" : fs::path(c.sources.file(range.file).path()).filename().string() + ":";
        return fmt::format("{}{}:{}", prefix, at.line, at.column);
    };
    for (const Diagnostic& d : c.diagnostics.items()) {
        if (d.warning == WarningKind::NoLights && !withNoLights) continue;
        const char* severity = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note";
        out.push_back(fmt::format("{} {} {}", severity, where(d.range), portable(d.message, paths)));
        for (const DiagnosticNote& n : d.notes) {
            out.push_back(fmt::format("  note {} {}", where(n.range), portable(n.message, paths)));
        }
    }
    return out;
}

bool compareLists(std::string_view what, const std::vector<std::string>& expected,
                  const std::vector<std::string>& actual) {
    if (expected == actual) return true;
    std::cerr << fmt::format("{} differ.\n  expected:\n", what);
    for (const std::string& s : expected) std::cerr << "    " << s << "\n";
    std::cerr << "  actual:\n";
    for (const std::string& s : actual) std::cerr << "    " << s << "\n";
    return false;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: golden_runner ROOT FILE.crt [--update]\n";
        return 2;
    }
    fs::path root = argv[1];
    fs::path file = argv[2];
    bool update = argc > 3 && std::string_view(argv[3]) == "--update";
    fs::current_path(root);
    unsetenv("CRT_PATH"); // include lookup must not depend on the environment
    PathPlaceholders paths;
    for (const fs::path& dir : {fs::path(CRT_SOURCE_STDLIB_DIR), fs::current_path()}) {
        std::string placeholder = dir == fs::current_path() ? "<golden>" : "<stdlib>";
        std::error_code error;
        for (fs::path form : {fs::absolute(dir).lexically_normal(), fs::weakly_canonical(dir, error)}) {
            std::string text = form.string();
            while (text.size() > 1 && text.back() == '/') text.pop_back();
            if (!text.empty()) paths.emplace_back(text, placeholder);
        }
    }
    // Longest first, so a path inside another is not half-replaced.
    std::stable_sort(paths.begin(), paths.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    std::string text = readText(file);
    Expectations expected = readExpectations(text);

    std::vector<std::string> argStrings = {"crtc"};
    argStrings.insert(argStrings.end(), expected.args.begin(), expected.args.end());
    argStrings.push_back(file.string());
    std::vector<char*> args;
    for (std::string& s : argStrings) args.push_back(s.data());
    crtc::ParsedOptions parsed = crtc::parseOptions(static_cast<int>(args.size()), args.data());
    if (!parsed.options) {
        std::cerr << parsed.message << "\n";
        return 2;
    }
    crtc::Options& options = *parsed.options;
    std::ostringstream printed;
    options.eval.printOut = &printed;
    options.eval.includes.stdlibDir = CRT_SOURCE_STDLIB_DIR;
    options.eval.frameCount = std::max(options.frames.count, 1);
    options.eval.frame = options.eval.frameCount - 1; // the last frame, where t is largest

    Compilation c = compile(file.string(), text, options.eval);
    if (options.werror) c.diagnostics.promoteWarnings();

    std::vector<std::string> printedLines;
    std::istringstream printedStream(printed.str());
    for (std::string line; std::getline(printedStream, line);) printedLines.emplace_back(trim(line));

    bool ok = compareLists("printed lines", expected.printed, printedLines);
    std::vector<std::string> expectedDiagnostics = expected.diagnostics;
    const bool withNoLights =
        std::any_of(expectedDiagnostics.begin(), expectedDiagnostics.end(),
                    [](const std::string& d) { return d.find("no lights") != std::string::npos; });
    std::vector<std::string> actualDiagnostics = describe(c, paths, withNoLights);
    ok = compareLists("diagnostics", expectedDiagnostics, actualDiagnostics) && ok;

    fs::path snapshot = fs::path(file).replace_extension(".scene.json");
    if (fs::exists(snapshot) || update) {
        std::string actual = c.scene ? replacePaths(scene::sceneToJson(*c.scene), paths) : std::string("null\n");
        if (update) {
            std::ofstream(snapshot) << actual;
        } else if (readText(snapshot) != actual) {
            std::cerr << fmt::format("--dump-scene differs from {}; to accept the new output after "
                                     "reviewing it, run: golden_runner {} {} --update\n",
                                     snapshot.string(), root.string(), file.string());
            ok = false;
        }
    }
    if (!ok) {
        PrintOptions print;
        std::cerr << "\nfull diagnostics:\n";
        printDiagnostics(std::cerr, c.sources, c.diagnostics, print);
    }
    return ok ? 0 : 1;
}
