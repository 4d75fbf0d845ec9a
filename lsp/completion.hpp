// Completion: attributes inside objects, typed values after '->', names, types and keywords.
#pragma once

#include "analysis.hpp"

#include <string>
#include <vector>

namespace crt::lsp {

enum class CompletionKind : uint8_t { Keyword, Type, Property, Variable, Function, Macro, Value, File, Snippet };

struct CompletionItem {
    std::string label;
    CompletionKind kind = CompletionKind::Variable;
    std::string detail;
    std::string documentation; ///< markdown
    std::string insertText;    ///< a snippet when `snippet`, else plain text
    bool snippet = false;
    std::string sortText;
};

struct CompletionList {
    lang::SourceRange replace; ///< the word being typed (empty at the cursor when none)
    std::vector<CompletionItem> items;
};

/// Completions at `offset`. Works from the tokens around the cursor, so it works while the
/// file has syntax errors; the index adds the names in scope.
CompletionList complete(const Analysis& analysis, uint32_t offset, const AnalysisOptions& options);
/// The same from the tokens of `current` (lexOnly() is enough) and the names in scope of
/// `names`, an older analysis of the document that sameNamesAt() found to have the same names
/// at `namesOffset` (where `offset` lies in its text).
CompletionList complete(const Analysis& current, uint32_t offset, const Analysis& names, uint32_t namesOffset,
                        const AnalysisOptions& options);

/// A snippet's text without its placeholders' markup: "vec3(${1:0}, 0)" -> "vec3(0, 0)".
std::string snippetToPlain(std::string_view snippet);

} // namespace crt::lsp
