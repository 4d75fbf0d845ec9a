// JSON forms of the features' results, and position conversion.
#include "protocol.hpp"

#include <fmt/format.h>

#include <charconv>

namespace crt::lsp {

using namespace lang;

std::pair<uint32_t, uint32_t> Positions::lineCharacter(uint32_t offset) const {
    if (encoding_ == OffsetEncoding::Utf16) {
        Utf16Position p = file_.utf16(offset);
        return {p.line, p.character};
    }
    uint32_t line = file_.lineColumn(offset).line;
    uint32_t clamped = std::min(offset, file_.size());
    return {line - 1, clamped - std::min(clamped, file_.lineStart(line))};
}

json Positions::position(uint32_t offset) const {
    auto [line, character] = lineCharacter(offset);
    return {{"line", line}, {"character", character}};
}

json Positions::range(SourceRange range) const {
    return {{"start", position(range.begin)}, {"end", position(std::max(range.begin, range.end))}};
}

uint32_t Positions::offset(const json& position) const {
    const json& line = member(position, "line");
    const json& character = member(position, "character");
    if (!line.is_number_integer() || !character.is_number_integer() || line.get<int64_t>() < 0 ||
        character.get<int64_t>() < 0) {
        throw LspError(ErrorCode::InvalidParams, "a position needs non-negative integer line and character");
    }
    uint64_t l = line.get<uint64_t>();
    uint64_t c = character.get<uint64_t>();
    if (l >= file_.lineCount()) return file_.size();
    uint32_t ch = static_cast<uint32_t>(std::min<uint64_t>(c, UINT32_MAX));
    if (encoding_ == OffsetEncoding::Utf16) return file_.offsetOf(Utf16Position{static_cast<uint32_t>(l), ch});
    return file_.offsetOfUtf8(static_cast<uint32_t>(l), ch);
}

const json& member(const json& object, const char* name) {
    if (!object.is_object() || !object.contains(name)) {
        throw LspError(ErrorCode::InvalidParams, fmt::format("missing parameter '{}'", name));
    }
    return object.at(name);
}

std::string uriToPath(std::string_view uri) {
    if (!uri.starts_with("file://")) return std::string(uri);
    std::string_view rest = uri.substr(7);
    std::string path;
    for (size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '%' && i + 2 < rest.size() && std::isxdigit(static_cast<unsigned char>(rest[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(rest[i + 2]))) {
            path += static_cast<char>(std::stoi(std::string(rest.substr(i + 1, 2)), nullptr, 16));
            i += 2;
        } else {
            path += rest[i];
        }
    }
    return path;
}

std::string pathToUri(std::string_view path) {
    std::string uri = "file://";
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
            uri += static_cast<char>(c);
        } else {
            uri += fmt::format("%{:02X}", c);
        }
    }
    return uri;
}

json toJson(const DocumentDiagnostic& d, const Positions& positions, const std::string& documentUri,
            const lang::SourceFile* documentFile, OffsetEncoding encoding) {
    json out{{"range", positions.range(d.range)},
             {"severity", d.severity == Severity::Error ? 1 : d.severity == Severity::Warning ? 2 : 3},
             {"source", "crt"},
             {"message", d.message}};
    if (!d.code.empty()) out["code"] = d.code;
    if (d.code == "unused-variable") out["tags"] = json::array({1}); // Unnecessary: editors fade it
    if (!d.related.empty()) {
        json related = json::array();
        for (const RelatedInfo& r : d.related) {
            Positions at(*r.file, encoding);
            std::string uri = r.file == documentFile ? documentUri : pathToUri(r.file->path());
            related.push_back({{"location", {{"uri", uri}, {"range", at.range(r.range)}}}, {"message", r.message}});
        }
        out["relatedInformation"] = std::move(related);
    }
    return out;
}

json toJson(const Hover& hover, const Positions& positions) {
    return {{"contents", {{"kind", "markdown"}, {"value", hover.markdown}}}, {"range", positions.range(hover.range)}};
}

namespace {

int completionKind(CompletionKind kind) {
    switch (kind) {
    case CompletionKind::Keyword: return 14;
    case CompletionKind::Type: return 7;      // Class
    case CompletionKind::Property: return 10;
    case CompletionKind::Variable: return 6;
    case CompletionKind::Function: return 3;
    case CompletionKind::Macro: return 3;
    case CompletionKind::Value: return 12;
    case CompletionKind::File: return 17;
    case CompletionKind::Snippet: return 15;
    }
    return 1;
}

int outlineKind(OutlineKind kind) {
    switch (kind) {
    case OutlineKind::File: return 1;
    case OutlineKind::Namespace: return 3;
    case OutlineKind::Object: return 19;
    case OutlineKind::Property: return 7;
    case OutlineKind::Function: return 12;
    case OutlineKind::Variable: return 13;
    case OutlineKind::Constant: return 14;
    }
    return 13;
}

} // namespace

json toJson(const CompletionList& list, const Positions& positions, bool snippets) {
    json items = json::array();
    json range = positions.range(list.replace);
    for (const CompletionItem& item : list.items) {
        json out{{"label", item.label}, {"kind", completionKind(item.kind)}};
        if (!item.detail.empty()) out["detail"] = item.detail;
        if (!item.documentation.empty()) out["documentation"] = {{"kind", "markdown"}, {"value", item.documentation}};
        bool snippet = item.snippet && snippets;
        std::string text = item.snippet && !snippets ? snippetToPlain(item.insertText) : item.insertText;
        out["textEdit"] = {{"range", range}, {"newText", text}};
        out["insertTextFormat"] = snippet ? 2 : 1;
        out["sortText"] = item.sortText + item.label;
        out["filterText"] = item.label;
        items.push_back(std::move(out));
    }
    return {{"isIncomplete", false}, {"items", std::move(items)}};
}

json toJson(const SignatureHelp& help) {
    json parameters = json::array();
    for (auto [begin, end] : help.parameters) parameters.push_back({{"label", json::array({begin, end})}});
    json signature{{"label", help.label}, {"parameters", parameters}};
    if (!help.documentation.empty()) signature["documentation"] = help.documentation;
    return {{"signatures", json::array({signature})}, {"activeSignature", 0}, {"activeParameter", help.activeParameter}};
}

json toJson(const DocumentSymbol& symbol, const Positions& positions) {
    json children = json::array();
    for (const DocumentSymbol& child : symbol.children) children.push_back(toJson(child, positions));
    json out{{"name", symbol.name.empty() ? std::string("?") : symbol.name},
             {"kind", outlineKind(symbol.kind)},
             {"range", positions.range(symbol.range)},
             {"selectionRange", positions.range(symbol.selection)},
             {"children", std::move(children)}};
    if (!symbol.detail.empty()) out["detail"] = symbol.detail;
    return out;
}

json toJson(const FoldingRange& range) {
    json out{{"startLine", range.startLine}, {"endLine", range.endLine}};
    if (range.comment) out["kind"] = "comment";
    return out;
}

std::string encodeSemanticTokens(const std::vector<SemanticToken>& tokens, const Positions& positions) {
    // Tokens come in order: walk the text once instead of converting each position alone
    // (a full-file request on a large script has tens of thousands of tokens).
    const SourceFile& file = positions.file();
    std::string_view text = file.text();
    bool utf16 = positions.encoding() == OffsetEncoding::Utf16;
    auto units = [&](uint32_t from, uint32_t to) {
        if (!utf16) return to - from;
        uint32_t n = 0;
        for (uint32_t i = from; i < to; ++i) {
            auto c = static_cast<unsigned char>(text[i]);
            if ((c & 0xC0) != 0x80) n += c >= 0xF0 ? 2 : 1; // a code point past U+FFFF is two units
        }
        return n;
    };
    std::vector<uint32_t> data;
    data.reserve(tokens.size() * 5);
    uint32_t line = 0, lineStart = file.lineStart(1), nextStart = file.lineStart(2);
    uint32_t lastLine = 0, lastStart = 0;
    uint32_t cursor = lineStart, cursorUnits = 0; // a known position on the current line
    for (const SemanticToken& t : tokens) {
        if (t.range.begin < cursor || t.range.end > text.size() || t.range.end <= t.range.begin) continue;
        while (line + 1 < file.lineCount() && nextStart <= t.range.begin) {
            ++line;
            lineStart = nextStart;
            nextStart = file.lineStart(line + 2);
            cursor = lineStart;
            cursorUnits = 0;
        }
        if (t.range.end > nextStart && line + 1 < file.lineCount()) continue; // never spans lines
        uint32_t start = cursorUnits + units(cursor, t.range.begin);
        uint32_t length = units(t.range.begin, t.range.end);
        cursor = t.range.end;
        cursorUnits = start + length;
        data.push_back(line - lastLine);
        data.push_back(line == lastLine ? start - lastStart : start);
        data.push_back(length);
        data.push_back(static_cast<uint32_t>(t.type));
        data.push_back(t.modifiers);
        lastLine = line;
        lastStart = start;
    }
    std::string out = "{\"data\":[";
    out.resize(out.size() + data.size() * 11 + 2); // at most 10 digits and a comma each
    char* p = out.data() + 9;
    char* end = out.data() + out.size();
    for (size_t i = 0; i < data.size(); ++i) {
        if (i) *p++ = ',';
        p = std::to_chars(p, end, data[i]).ptr;
    }
    *p++ = ']';
    *p++ = '}';
    out.resize(static_cast<size_t>(p - out.data()));
    return out;
}

} // namespace crt::lsp
