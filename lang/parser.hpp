// Parsing a CRT script into an AST (spec §2), with error recovery.
#pragma once

#include "ast.hpp"
#include "diagnostic.hpp"
#include "token.hpp"

#include <vector>

namespace crt::lang {

/// Parses `file` (registered as `fileIndex`) into nodes allocated in `arena`. Syntax errors
/// are reported to `diagnostics`; the returned script holds everything that could be parsed.
/// When `comments` is given, the comment tokens are appended to it.
Script parse(const SourceFile& file, uint32_t fileIndex, Arena& arena, DiagnosticBag& diagnostics,
             std::vector<Token>* comments = nullptr);

} // namespace crt::lang
