// The re2c lexer for CRT scripts (spec §1): tokens with byte ranges and lexical diagnostics.
#pragma once

#include "diagnostic.hpp"
#include "token.hpp"

#include <vector>

namespace crt::lang {

class Lexer {
public:
    /// `fileIndex` is stored in the ranges of the diagnostics it reports.
    Lexer(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics);

    /// The next token, comments and whitespace skipped. After the end, EndOfFile forever.
    /// Inline: the parser asks for every token through it.
    Token next() {
        Token token;
        if (hasPending_) [[unlikely]] {
            hasPending_ = false;
            token = pending_;
        } else {
            token = scan();
        }
        if (token.kind == TokenKind::Less) [[unlikely]] classifyLess(token);
        return token;
    }
    /// Comments seen so far are appended here (for semantic highlighting and folding).
    void collectComments(std::vector<Token>* comments) { comments_ = comments; }

private:
    Token scan();
    /// A '<' opens a modifier list exactly when the next token is a modifier keyword; that
    /// token is kept for the next call.
    void classifyLess(Token& less);
    Token scanString(const char* start);
    void reportInvalid(const char* start, const char* end);
    uint32_t offset(const char* p) const { return static_cast<uint32_t>(p - begin_); }
    SourceRange range(const char* start, const char* end) const {
        return {fileIndex_, offset(start), offset(end)};
    }

    const char* begin_;
    const char* end_;
    const char* cursor_;
    uint32_t fileIndex_;
    DiagnosticBag& diagnostics_;
    std::vector<Token>* comments_ = nullptr;
    bool lineStart_ = true;
    bool hasPending_ = false;
    Token pending_;
};

/// Lexes a whole file (for tests and tools): every token but the final EndOfFile.
std::vector<Token> lexAll(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics,
                          std::vector<Token>* comments = nullptr);

} // namespace crt::lang
