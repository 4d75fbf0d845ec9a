// The re2c lexer for CRT scripts (spec §1): tokens with byte ranges and lexical diagnostics.
#pragma once

#include "diagnostic.hpp"
#include "token.hpp"

#include <optional>
#include <vector>

namespace crt::lang {

class Lexer {
public:
    /// `fileIndex` is stored in the ranges of the diagnostics it reports.
    Lexer(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics);

    /// The next token, comments and whitespace skipped. After the end, EndOfFile forever.
    Token next();
    /// Comments seen so far are appended here (for semantic highlighting and folding).
    void collectComments(std::vector<Token>* comments) { comments_ = comments; }

private:
    Token scan();
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
    std::optional<Token> pending_;
};

/// Lexes a whole file (for tests and tools): every token but the final EndOfFile.
std::vector<Token> lexAll(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics,
                          std::vector<Token>* comments = nullptr);

} // namespace crt::lang
