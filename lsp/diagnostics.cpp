// Converts the front end's diagnostics for the document: included files map to their include.
#include "diagnostics.hpp"

#include <fmt/format.h>

namespace crt::lsp {

using namespace lang;

std::string_view warningCode(WarningKind kind) {
    switch (kind) {
    case WarningKind::None: return "";
    case WarningKind::UnusedVariable: return "unused-variable";
    case WarningKind::EntityNeverDrawn: return "entity-never-drawn";
    case WarningKind::UnusedLight: return "unused-light";
    case WarningKind::DuplicateAttribute: return "duplicate-attribute";
    case WarningKind::ValueNotDrawn: return "value-not-drawn";
    case WarningKind::ShadowedBuiltin: return "shadowed-builtin";
    case WarningKind::ZeroSizeEntity: return "zero-size-entity";
    case WarningKind::EmptyScene: return "empty-scene";
    case WarningKind::DivisionByZero: return "division-by-zero";
    case WarningKind::OutsideScene: return "outside-scene";
    case WarningKind::NoLights: return "no-lights";
    case WarningKind::MissingGlyph: return "missing-glyph";
    }
    return "";
}

namespace {

/// The front end advises crtc's options for its limits; in an editor, the language server's
/// settings raise them (initialization options, and VS Code's settings of the same names).
struct LimitSetting {
    std::string_view crtcOption;
    std::string_view advice;
};
constexpr LimitSetting kLimitSettings[] = {
    {"--max-steps", "the language server's maxSteps setting (crt.maxSteps in VS Code)"},
    {"--max-entities", "the language server's maxEntities setting (crt.maxEntities in VS Code)"},
    {"--max-primitives",
     "the language server's maxPrimitives setting (crt.maxPrimitives in VS Code)"},
    {"--max-depth", "the language server's maxDepth setting"},
    {"--max-mesh-size", "the language server's maxMeshSize setting"},
    {"--max-text-length", "the language server's maxTextLength setting"},
    {"--max-memory", "the language server's maxMemory setting"},
};

/// `message` with crtc's limit options named as the settings that raise them in an editor.
std::string inEditorTerms(std::string message) {
    for (const LimitSetting& setting : kLimitSettings) {
        const std::string with = fmt::format("with {}", setting.crtcOption);
        const size_t at = message.find(with);
        // Whole options only: "--max-steps" but not the start of a longer option name.
        const size_t after = at + with.size();
        if (at != std::string::npos &&
            (after == message.size() || message[after] == ')' || message[after] == ';' ||
             message[after] == ' ' || message[after] == ','))
            message.replace(at, with.size(), fmt::format("with {}", setting.advice));
    }
    return message;
}

/// The first top-level include of the document: where problems of included files are shown.
SourceRange firstInclude(const Compilation& c) {
    for (const Node* item : c.main.items) {
        if (item->kind == NodeKind::Include) return item->range;
    }
    return {0, 0, 0};
}

} // namespace

std::vector<DocumentDiagnostic> documentDiagnostics(const Compilation& c) {
    std::vector<DocumentDiagnostic> result;
    const uint32_t files = c.sources.fileCount();
    const auto& items = c.diagnostics.items();
    for (size_t index = 0; index < items.size(); ++index) {
        const Diagnostic& d = items[index];
        if (result.size() + 1 == kMaxPublishedDiagnostics && index + 1 < items.size()) {
            // The last place says what was left out, at the first of those left out.
            DocumentDiagnostic more;
            more.range = d.range.file == 0 ? d.range : SourceRange{0, 0, 0};
            more.severity = Severity::Warning;
            more.message =
                fmt::format("{} more problems not shown (too many)", items.size() - index);
            result.push_back(std::move(more));
            break;
        }
        DocumentDiagnostic out;
        out.severity = d.severity;
        out.message = inEditorTerms(d.message);
        out.code = std::string(warningCode(d.warning));
        if (d.range.file == 0 && files > 0) {
            out.range = d.range;
        } else if (d.range.file < files) {
            const SourceFile& file = c.sources.file(d.range.file);
            LineColumn at = file.lineColumn(d.range.begin);
            out.range = firstInclude(c);
            out.message = fmt::format("{}:{}:{}: {}", file.path(), at.line, at.column,
                                      inEditorTerms(d.message));
            out.related.push_back({&file, d.range, inEditorTerms(d.message)});
        } else {
            out.range = {0, 0, 0}; // not in any file (an unreadable script)
        }
        for (const DiagnosticNote& note : d.notes) {
            if (note.range.file < files)
                out.related.push_back({&c.sources.file(note.range.file), note.range, note.message});
        }
        for (const FixIt& fix : d.fixits) {
            if (fix.range.file == 0 && d.range.file == 0) out.fixits.push_back(fix);
        }
        result.push_back(std::move(out));
    }
    return result;
}

} // namespace crt::lsp
