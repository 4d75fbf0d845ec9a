// State shared by the Bison parser's actions and its token source.
#pragma once

#include "ast.hpp"
#include "diagnostic.hpp"
#include "lexer.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace crt::lang {

/// A list under construction: `count` items from `start` in one of ParseContext's scratch
/// stacks. Lists nest, so each kind of list shares one stack, used last-in first-out.
struct ListMark {
    uint32_t start;
    uint32_t count;
};

/// The parser's location of a symbol: byte offsets in the file being parsed. The file index
/// is added when a node or a diagnostic is made (ParseContext::at), which keeps the parser's
/// stack entries small.
struct ParseRange {
    uint32_t begin = 0;
    uint32_t end = 0;
};

/// A token's text as the parser's semantic value (a plain pair, unlike string_view).
struct TextRef {
    const char* data;
    uint32_t size;
    operator std::string_view() const { return {data, size}; }
};

struct ParseContext {
    const SourceFile& file;
    uint32_t fileIndex;
    Arena& arena;
    DiagnosticBag& diagnostics;
    Lexer lexer;
    std::vector<Node*> items; ///< top-level items parsed so far
    // Scratch stacks for lists being parsed; semantic values stay small and trivially
    // copyable, with no allocation per list.
    std::vector<Node*> statementScratch;
    std::vector<Expr*> exprScratch;
    std::vector<Attribute> attributeScratch;
    std::vector<Modifier> modifierScratch;
    std::vector<Param> paramScratch;
    Token lastToken;          ///< the token most recently handed to the parser
    Token previousToken;      ///< the one before it
    // Error recovery: after a syntax error the token source skips to a resume point and
    // hands the parser RECOVERED before the token found there.
    bool recovering = false;
    bool skipping = false;           ///< drop tokens up to a resume point first
    int skipDepth = 0;               ///< braces already open when skipping starts
    std::vector<Token> queued;       ///< tokens to hand out (after RECOVERED) before lexing on
    uint32_t lastResumedAt = ~0u;    ///< never resume twice at one token: no endless loop
    uint32_t lastReportedAt = ~0u;   ///< never report twice at one token

    ParseContext(const SourceFile& f, uint32_t index, Arena& a, DiagnosticBag& d)
        : file(f), fileIndex(index), arena(a), diagnostics(d), lexer(f, index, d) {}

    SourceRange range(uint32_t begin, uint32_t end) const { return {fileIndex, begin, end}; }
    SourceRange at(ParseRange where) const { return {fileIndex, where.begin, where.end}; }
    std::string_view text(const Token& token) const {
        return file.text().substr(token.begin, token.end - token.begin);
    }

    /// A zero-initialised node of kind `kind` spanning `where`.
    template <typename T> T* node(NodeKind kind, SourceRange where) {
        T* result = arena.make<T>();
        result->kind = kind;
        result->range = where;
        return result;
    }
    // An attribute or a modifier is appended to its list by the very next reduction, so
    // one slot each carries it there (nested ones are appended before it is made).
    Attribute heldAttribute{};
    Modifier heldModifier{};
    Attribute* hold(const Attribute& attribute) { return &(heldAttribute = attribute); }
    Modifier* hold(const Modifier& modifier) { return &(heldModifier = modifier); }

    template <typename T> ListMark beginList(const std::vector<T>& scratch) {
        return {static_cast<uint32_t>(scratch.size()), 0};
    }
    /// Appends `item`, first dropping anything a syntax error left above the list's items.
    template <typename T> ListMark append(std::vector<T>& scratch, ListMark list, const T& item) {
        scratch.resize(list.start + list.count);
        scratch.push_back(item);
        return {list.start, list.count + 1};
    }
    /// Moves the list's items into the arena and pops them.
    template <typename T> std::span<T> finishList(std::vector<T>& scratch, ListMark list) {
        std::span<T> items;
        if (list.count > 0) {
            T* data = static_cast<T*>(arena.allocate(sizeof(T) * list.count, alignof(T)));
            std::copy_n(scratch.begin() + list.start, list.count, data);
            items = {data, list.count};
        }
        scratch.resize(list.start);
        return items;
    }

    /// The next token for the parser, after error recovery's skipping.
    /// Brackets lexed and not closed yet, innermost last: what an error at a missing closer
    /// points back to.
    std::vector<Token> openBrackets;
    uint32_t lastTokenEnd = 0; ///< where the last token before the end of the file ends

    Token nextToken() {
        Token token = lexNext();
        return skipping ? skipToResumePoint(token) : token;
    }
    /// The lexer's next token, with the open brackets kept up to date.
    Token lexNext() {
        Token token = lexer.next();
        switch (token.kind) {
        case TokenKind::LParen:
        case TokenKind::LParenLine:
        case TokenKind::LBrace:
        case TokenKind::LBracket:
        case TokenKind::LBracketLine: openBrackets.push_back(token); break;
        case TokenKind::RParen:
        case TokenKind::RBrace:
        case TokenKind::RBracket:
            if (!openBrackets.empty() && closerOf(openBrackets.back().kind) == token.kind) openBrackets.pop_back();
            break;
        default: break;
        }
        if (token.kind != TokenKind::EndOfFile) lastTokenEnd = token.end;
        return token;
    }
    static TokenKind closerOf(TokenKind opener) {
        switch (opener) {
        case TokenKind::LParen:
        case TokenKind::LParenLine: return TokenKind::RParen;
        case TokenKind::LBrace: return TokenKind::RBrace;
        default: return TokenKind::RBracket;
        }
    }
    /// Error recovery: drops tokens from `token` on up to a resume point, which it returns.
    Token skipToResumePoint(Token token);
    /// Decodes the escapes of a string token into the arena.
    std::string_view decodeString(const Token& token);
};

} // namespace crt::lang
