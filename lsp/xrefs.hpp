// Cross references: definition, references, document highlights and rename of names.
#pragma once

#include "analysis.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crt::lsp {

/// A range in the document (`file` is the analysis's own) or in an included file.
struct Location {
    const lang::SourceFile* file;
    lang::SourceRange range;
};

std::vector<Location> definition(const Analysis& analysis, uint32_t offset);
/// Every mention of the name at `offset`, in the document and in the files it includes.
std::vector<Location> references(const Analysis& analysis, uint32_t offset, bool includeDeclaration);

struct Highlight {
    lang::SourceRange range;
    bool write;
};
std::vector<Highlight> documentHighlights(const Analysis& analysis, uint32_t offset);

/// The word a rename at `offset` would change, or an error message.
struct RenameCheck {
    std::optional<lang::SourceRange> range;
    std::string placeholder;
    std::string error;
};
RenameCheck prepareRename(const Analysis& analysis, uint32_t offset, const AnalysisOptions& options);

struct RenameResult {
    std::vector<Location> edits; ///< each replaced by the new name
    std::string error;           ///< set when the rename is refused
};
RenameResult rename(const Analysis& analysis, uint32_t offset, std::string_view newName,
                    const AnalysisOptions& options);

} // namespace crt::lsp
