// A readable, indented dump of the AST.
#pragma once

#include "ast.hpp"

#include <string>

namespace crt::lang {

/// One line per node: its kind, its details and its position (line:column).
std::string dumpAst(const Script& script, const SourceFile& file);

} // namespace crt::lang
