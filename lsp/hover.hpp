// Hover: what a name, an object type, an attribute or a built-in is.
#pragma once

#include "analysis.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace crt::lsp {

/// Global values of the latest evaluation: name and text, as Compilation::globalValues.
using GlobalValues = std::vector<std::pair<std::string, std::string>>;

struct Hover {
    lang::SourceRange range; ///< the word hovered
    std::string markdown;
};

/// The hover for the token at `offset`; `values` (may be null) adds evaluated values.
std::optional<Hover> hover(const Analysis& analysis, uint32_t offset, const GlobalValues* values);

/// Markdown documentation of an object type: its doc and attribute table.
std::string objectTypeDoc(const lang::ObjectInfo& info);
/// Markdown documentation of one attribute.
std::string attributeDoc(const lang::ObjectInfo& owner, const lang::AttributeInfo& attribute);

} // namespace crt::lsp
