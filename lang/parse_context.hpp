// State shared by the Bison parser's actions and its token source.
#pragma once

#include "ast.hpp"
#include "diagnostic.hpp"
#include "lexer.hpp"

#include <string>
#include <vector>

namespace crt::lang {

struct ParseContext {
    const SourceFile& file;
    uint32_t fileIndex;
    Arena& arena;
    DiagnosticBag& diagnostics;
    Lexer lexer;
    std::vector<Node*> items; ///< top-level items parsed so far
    Token lastToken;          ///< the token most recently handed to the parser
    bool skipping = false;    ///< after a syntax error: drop tokens up to a resume point
    int skipDepth = 0;        ///< braces already open when skipping starts

    ParseContext(const SourceFile& f, uint32_t index, Arena& a, DiagnosticBag& d)
        : file(f), fileIndex(index), arena(a), diagnostics(d), lexer(f, index, d) {}

    SourceRange range(uint32_t begin, uint32_t end) const { return {fileIndex, begin, end}; }
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
    /// The next token for the parser, after error recovery's skipping.
    Token nextToken();
    /// Decodes the escapes of a string token into the arena.
    std::string_view decodeString(const Token& token);
};

} // namespace crt::lang
