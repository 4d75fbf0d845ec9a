// GCC/Clang-style rendering of diagnostics.
#include "diagnostic_printer.hpp"

#include "terminal_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>

namespace crt::lang {
namespace {

constexpr const char* kBold = "\033[1m";
constexpr const char* kReset = "\033[0m";
constexpr const char* kRed = "\033[1;31m";
constexpr const char* kMagenta = "\033[1;35m";
constexpr const char* kCyan = "\033[1;36m";
constexpr const char* kGreen = "\033[1;32m";

const char* severityName(Severity severity) {
    switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    }
    return "error";
}

const char* severityColor(Severity severity) {
    switch (severity) {
    case Severity::Error: return kRed;
    case Severity::Warning: return kMagenta;
    case Severity::Note: return kCyan;
    }
    return kRed;
}

/// The columns `text` takes once terminalSafe has escaped it (a tab counts as one: it is
/// copied under itself).
uint32_t displayWidth(std::string_view text) {
    uint32_t width = 0;
    std::string shown;
    for (size_t at = 0; at < text.size();) {
        if (text[at] == '\t') {
            ++width, ++at;
            continue;
        }
        at += nextCharacter(text, at, shown).size();
        width += shown.starts_with('\\') ? static_cast<uint32_t>(shown.size()) : 1;
    }
    return width;
}

/// The source line of `range` with a caret under its start and tildes under the rest
/// (clipped to the first line).
void appendSnippet(std::string& out, const SourceFile& file, SourceRange range,
                   const PrintOptions& options, const std::string* replacement) {
    LineColumn start = file.lineColumn(range.begin);
    std::string_view line = file.lineText(start.line);
    uint32_t lineBegin = file.lineStart(start.line);
    uint32_t lineEnd = lineBegin + static_cast<uint32_t>(line.size());
    // Within the line: a range at the start of a file may begin inside its byte-order mark,
    // before the first line's text.
    const uint32_t begin = std::clamp(range.begin, lineBegin, lineEnd);
    uint32_t width = range.end > begin ? displayWidth(file.text().substr(begin, std::min(range.end, lineEnd) - begin))
                                       : 0;
    // A very long line (generated code) is shown as a window around the caret.
    constexpr uint32_t kWindow = 120;
    std::string_view shown = line;
    std::string_view lead, trail;
    uint32_t caretByte = begin - lineBegin;
    if (line.size() > 2 * kWindow) {
        uint32_t from = caretByte > kWindow / 2 ? caretByte - kWindow / 2 : 0;
        while (from > 0 && (static_cast<unsigned char>(line[from]) & 0xC0) == 0x80) --from;
        uint32_t to = std::min<uint32_t>(static_cast<uint32_t>(line.size()), from + kWindow);
        while (to < line.size() && (static_cast<unsigned char>(line[to]) & 0xC0) == 0x80) ++to;
        shown = line.substr(from, to - from);
        lead = from > 0 ? "..." : "";
        trail = to < line.size() ? "..." : "";
        lineBegin += from;
        caretByte -= from;
        width = std::min(width, displayWidth(line.substr(from + caretByte, to - caretByte - from)));
    }
    out += fmt::format("    {}{}{}\n    {}", lead, terminalSafe(shown), trail,
                       std::string(lead.size(), ' '));
    // Tabs in the prefix are copied so the caret lines up in a terminal; an escaped byte
    // takes the columns of its escape.
    std::string_view prefix = shown.substr(0, caretByte);
    uint32_t column = 1;
    std::string escaped;
    for (size_t at = 0; at < prefix.size();) {
        if (prefix[at] == '\t') {
            out += '\t', ++column, ++at;
            continue;
        }
        at += nextCharacter(prefix, at, escaped).size();
        const uint32_t columns = escaped.starts_with('\\') ? static_cast<uint32_t>(escaped.size()) : 1;
        out.append(columns, ' ');
        column += columns;
    }
    if (options.color) out += kGreen;
    out += '^';
    for (uint32_t i = 1; i < width; ++i) out += '~';
    if (options.color) out += kReset;
    out += '\n';
    if (replacement) {
        out += "    ";
        out.append(column - 1, ' ');
        if (options.color) out += kGreen;
        out += terminalSafe(*replacement, true);
        if (options.color) out += kReset;
        out += '\n';
    }
}

void appendHeader(std::string& out, const SourceManager& sources, SourceRange range,
                  Severity severity, const std::string& message, const PrintOptions& options) {
    if (options.color) out += kBold;
    out += terminalSafe(formatLocation(sources, range), true);
    out += ": ";
    if (options.color) out += severityColor(severity);
    out += severityName(severity);
    out += ": ";
    if (options.color) out += kReset, out += kBold;
    out += terminalSafe(message);
    if (options.color) out += kReset;
    out += '\n';
}

/// Whether a diagnostic in file `index` shows its source line: always for the main script
/// (file 0), which the user named; for another file only if it is a script (.crt) or a mesh
/// (.obj) the script names, so that an include of another kind of file (allowed by
/// --allow-read) is not printed line by line.
bool quotesLines(const SourceManager& sources, uint32_t index) {
    if (index == 0) return true;
    if (index >= sources.fileCount()) return false;
    std::string extension = std::filesystem::path(sources.file(index).path()).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".crt" || extension == ".obj";
}

} // namespace

std::string formatLocation(const SourceManager& sources, SourceRange range) {
    if (range.file >= sources.fileCount()) return "<unknown>";
    const SourceFile& file = sources.file(range.file);
    LineColumn position = file.lineColumn(range.begin);
    return fmt::format("{}:{}:{}", file.path(), position.line, position.column);
}

std::string formatDiagnostic(const SourceManager& sources, const Diagnostic& diagnostic,
                             const PrintOptions& options) {
    std::string out;
    bool known = diagnostic.range.file < sources.fileCount();
    appendHeader(out, sources, diagnostic.range, diagnostic.severity, diagnostic.message,
                 options);
    if (known && options.sourceLines && quotesLines(sources, diagnostic.range.file)) {
        // A replacement is shown under the caret only when it applies right there.
        const std::string* replacement = nullptr;
        if (!diagnostic.fixits.empty() && diagnostic.fixits.front().range.begin == diagnostic.range.begin &&
            !diagnostic.fixits.front().replacement.empty()) {
            replacement = &diagnostic.fixits.front().replacement;
        }
        appendSnippet(out, sources.file(diagnostic.range.file), diagnostic.range, options,
                      replacement);
    }
    for (const DiagnosticNote& note : diagnostic.notes) {
        appendHeader(out, sources, note.range, Severity::Note, note.message, options);
        if (options.sourceLines && quotesLines(sources, note.range.file)) {
            appendSnippet(out, sources.file(note.range.file), note.range, options, nullptr);
        }
    }
    return out;
}

void printDiagnostics(std::ostream& out, const SourceManager& sources,
                      const DiagnosticBag& diagnostics, const PrintOptions& options) {
    for (const Diagnostic& diagnostic : diagnostics.items()) {
        out << formatDiagnostic(sources, diagnostic, options);
    }
}

} // namespace crt::lang
