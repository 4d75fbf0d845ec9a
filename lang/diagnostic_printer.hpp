// Prints diagnostics in the GCC/Clang form, with the source line and a caret underline.
#pragma once

#include "diagnostic.hpp"

#include <iosfwd>
#include <string>

namespace crt::lang {

struct PrintOptions {
    bool color = false;
    bool sourceLines = true;
};

/// "file:line:col: error: message" followed by the line, the caret and the notes.
std::string formatDiagnostic(const SourceManager& sources, const Diagnostic& diagnostic,
                             const PrintOptions& options = {});
void printDiagnostics(std::ostream& out, const SourceManager& sources,
                      const DiagnosticBag& diagnostics, const PrintOptions& options = {});
/// "file:line:col" for a range.
std::string formatLocation(const SourceManager& sources, SourceRange range);

} // namespace crt::lang
