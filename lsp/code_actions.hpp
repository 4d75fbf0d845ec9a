// Code actions: the front end's fix-its (did-you-mean, add a missing attribute) as quick fixes.
#pragma once

#include "diagnostics.hpp"

#include <string>
#include <vector>

namespace crt::lsp {

struct TextEdit {
    lang::SourceRange range;
    std::string newText;
};

struct CodeAction {
    std::string title;
    std::vector<TextEdit> edits;
    size_t diagnostic; ///< index into the diagnostics given
    bool preferred = false;
};

/// Quick fixes for the diagnostics overlapping [begin, end].
std::vector<CodeAction> codeActions(const std::vector<DocumentDiagnostic>& diagnostics, std::string_view text,
                                    uint32_t begin, uint32_t end);

} // namespace crt::lsp
