// Classifies tokens: lexer kinds for literals and keywords, the index for names.
#include "semantic_tokens.hpp"

#include "builtins.hpp"

#include <algorithm>

namespace crt::lsp {

using namespace lang;

const std::vector<std::string_view>& tokenTypeNames() {
    static const std::vector<std::string_view> names{
        "keyword", "type", "property", "variable", "parameter", "macro",
        "function", "number", "string", "comment", "operator"};
    return names;
}

const std::vector<std::string_view>& tokenModifierNames() {
    static const std::vector<std::string_view> names{"declaration", "definition", "readonly",
                                                      "defaultLibrary"};
    return names;
}

namespace {

std::optional<SemanticToken> classify(const Analysis& a, size_t index) {
    const Token& t = a.tokens[index];
    SourceRange range{0, t.begin, t.end};
    switch (t.kind) {
    case TokenKind::Integer:
    case TokenKind::Float: return SemanticToken{range, TokenType::Number};
    case TokenKind::String: return SemanticToken{range, TokenType::String};
    case TokenKind::Name: {
        bool known = findObjectType(a.text(t)) != ObjectType::Count;
        return SemanticToken{range, TokenType::Type, known ? uint32_t{ModDefaultLibrary} : 0u};
    }
    case TokenKind::Identifier: {
        if (const Occurrence* o = a.occurrenceAt(t.begin); o && o->range.begin == t.begin) {
            const Symbol& s = a.symbols[o->symbol];
            uint32_t mods = o->definition ? (ModDeclaration | ModDefinition) : 0;
            switch (s.kind) {
            case SymbolKind::Builtin: {
                auto slot = findPreludeSlot(s.name);
                bool function = slot && *slot < preludeSlotOfT();
                return SemanticToken{range, function ? TokenType::Function : TokenType::Variable,
                                     ModReadonly | ModDefaultLibrary};
            }
            case SymbolKind::Parameter: return SemanticToken{range, TokenType::Parameter, mods};
            case SymbolKind::Macro: return SemanticToken{range, TokenType::Macro, mods};
            default: return SemanticToken{range, TokenType::Variable, mods};
            }
        }
        // An identifier before '->' names an attribute, even where the parse failed.
        if (index + 1 < a.tokens.size() && a.tokens[index + 1].kind == TokenKind::Arrow) {
            return SemanticToken{range, TokenType::Property};
        }
        // `v.x`: a component's name.
        if (index > 0 && a.tokens[index - 1].kind == TokenKind::Dot)
            return SemanticToken{range, TokenType::Property};
        // `<material m>`, `<shadow false>`: words of the modifier list where no name is meant.
        if (namedModifier(a.text(t)) && index > 0 &&
            (a.tokens[index - 1].kind == TokenKind::ModifierOpen || a.tokens[index - 1].kind == TokenKind::Comma))
            return SemanticToken{range, TokenType::Keyword};
        if (auto slot = findPreludeSlot(a.text(t))) {
            bool function = *slot < preludeSlotOfT();
            return SemanticToken{range, function ? TokenType::Function : TokenType::Variable,
                                 ModReadonly | ModDefaultLibrary};
        }
        return SemanticToken{range, TokenType::Variable};
    }
    case TokenKind::LParen: case TokenKind::LParenLine: case TokenKind::RParen:
    case TokenKind::LBrace: case TokenKind::RBrace: case TokenKind::LBracket:
    case TokenKind::LBracketLine: case TokenKind::RBracket: case TokenKind::Comma:
    case TokenKind::EndOfFile: case TokenKind::Invalid: case TokenKind::Comment:
        return std::nullopt;
    default:
        if (isKeyword(t.kind)) return SemanticToken{range, TokenType::Keyword};
        return SemanticToken{range, TokenType::Operator};
    }
}

} // namespace

std::vector<SemanticToken> semanticTokens(const Analysis& a, std::optional<SourceRange> within) {
    std::vector<SemanticToken> result;
    result.reserve(a.tokens.size() + a.comments.size());
    auto inside = [&](uint32_t begin, uint32_t end) {
        return !within || (end >= within->begin && begin <= within->end);
    };
    size_t c = 0;
    auto flushComments = [&](uint32_t before) {
        for (; c < a.comments.size() && a.comments[c].begin < before; ++c) {
            const Token& t = a.comments[c];
            if (inside(t.begin, t.end)) result.push_back({{0, t.begin, t.end}, TokenType::Comment, 0});
        }
    };
    for (size_t i = 0; i < a.tokens.size(); ++i) {
        const Token& t = a.tokens[i];
        flushComments(t.begin);
        if (!inside(t.begin, t.end)) continue;
        if (auto token = classify(a, i)) result.push_back(*token);
    }
    flushComments(~0u);
    return result;
}

} // namespace crt::lsp
