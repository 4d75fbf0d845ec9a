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
        if (pendingCount_ > 0) [[unlikely]] {
            token = pending_[0];
            pending_[0] = pending_[1];
            pending_[1] = pending_[2];
            --pendingCount_;
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
    /// A '<' opens a modifier list when what follows can only be one: a modifier keyword,
    /// `material` or `matrix` before an operand, or a name closed by '>' (`<spin>`) or
    /// followed by ',' and a modifier (keyword, `material` or `matrix`). The tokens looked
    /// at are kept for next().
    void classifyLess(Token& less);
    /// The token `k` places after the last one returned, scanned now if need be.
    const Token& peek(int k) {
        while (pendingCount_ <= k) pending_[pendingCount_++] = scan();
        return pending_[k];
    }
    std::string_view text(const Token& token) const {
        return {begin_ + token.begin, static_cast<size_t>(token.end - token.begin)};
    }
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
    int pendingCount_ = 0;
    Token pending_[3];
};

/// Lexes a whole file (for tests and tools): every token but the final EndOfFile.
std::vector<Token> lexAll(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics,
                          std::vector<Token>* comments = nullptr);

} // namespace crt::lang
