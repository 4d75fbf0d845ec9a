// Semantic tokens: every token of the document classified with the resolver's knowledge.
#pragma once

#include "analysis.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace crt::lsp {

/// Token types, in the order of the legend the server announces.
enum class TokenType : uint8_t {
    Keyword, Type, Property, Variable, Parameter, Macro, Function, Number, String, Comment, Operator,
};
/// Token modifiers, as bits in the order of the legend.
enum TokenModifier : uint32_t {
    ModDeclaration = 1u << 0,
    ModDefinition = 1u << 1,
    ModReadonly = 1u << 2,
    ModDefaultLibrary = 1u << 3,
};

const std::vector<std::string_view>& tokenTypeNames();
const std::vector<std::string_view>& tokenModifierNames();

struct SemanticToken {
    lang::SourceRange range; ///< never spans lines
    TokenType type;
    uint32_t modifiers = 0;
};

/// The classified tokens of the document in order; only those overlapping `within` if given.
std::vector<SemanticToken> semanticTokens(const Analysis& analysis,
                                          std::optional<lang::SourceRange> within = std::nullopt);

} // namespace crt::lsp
