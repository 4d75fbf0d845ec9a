// The diagnostics of one evaluation, placed in the document being edited.
#pragma once

#include "interpreter.hpp"

#include <string>
#include <vector>

namespace crt::lsp {

/// A note of a diagnostic, possibly in another file.
struct RelatedInfo {
    const lang::SourceFile* file; ///< where `range` is
    lang::SourceRange range;
    std::string message;
};

/// One diagnostic with its range in the document (file 0 of the compilation).
struct DocumentDiagnostic {
    lang::SourceRange range;
    lang::Severity severity = lang::Severity::Error;
    std::string message;
    std::string code; ///< the warning's name ("unused-variable"), empty for errors
    std::vector<RelatedInfo> related;
    std::vector<lang::FixIt> fixits; ///< only those inside the document
};

/// At most this many diagnostics are published for a document: an editor cannot show more
/// usefully, and a binary file opened as a script makes millions.
inline constexpr size_t kMaxPublishedDiagnostics = 200;

/// The diagnostics of `compilation`, in report order, at most kMaxPublishedDiagnostics (the
/// last then says how many were left out). A problem inside an included file
/// is shown at the `include` that reaches it, with the file's own location in the message.
std::vector<DocumentDiagnostic> documentDiagnostics(const lang::Compilation& compilation);

/// The name of a warning kind as a diagnostic code ("unused-variable").
std::string_view warningCode(lang::WarningKind kind);

} // namespace crt::lsp
