// The outline: assignments, objects with their attributes, macros, Settings and Scene blocks.
#pragma once

#include "analysis.hpp"

#include <string>
#include <vector>

namespace crt::lsp {

enum class OutlineKind : uint8_t { File, Namespace, Object, Property, Function, Variable, Constant };

struct DocumentSymbol {
    std::string name;
    std::string detail;
    OutlineKind kind = OutlineKind::Variable;
    lang::SourceRange range;     ///< the whole construct
    lang::SourceRange selection; ///< its name
    std::vector<DocumentSymbol> children;
};

std::vector<DocumentSymbol> documentSymbols(const Analysis& analysis);

} // namespace crt::lsp
