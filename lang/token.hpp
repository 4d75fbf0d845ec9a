// Token kinds produced by the lexer (spec §1).
#pragma once

#include "source_file.hpp"

#include <cstdint>
#include <string_view>

namespace crt::lang {

enum class TokenKind : uint8_t {
    EndOfFile,
    Invalid, ///< a character that starts no token, or a malformed literal (already reported)
    Identifier,
    Name,
    Integer,
    Float,
    String,
    // keywords
    KwSettings,
    KwScene,
    KwMacro,
    KwFunction,
    KwScale,
    KwTranslate,
    KwRotate,
    KwTrue,
    KwFalse,
    KwWhile,
    KwFor,
    KwIn,
    KwIf,
    KwElse,
    KwInclude,
    // punctuation
    LParen,     ///< '(' that may be a call
    LParenLine, ///< '(' first on its line: never a call
    RParen,
    LBrace,
    RBrace,
    LBracket,     ///< '[' that may be an index
    LBracketLine, ///< '[' first on its line: never an index
    RBracket,
    Comma,
    Arrow,
    Assign,
    PlusAssign,  ///< +=
    MinusAssign, ///< -=
    StarAssign,  ///< *=
    SlashAssign, ///< /=
    Plus,
    Minus,
    Caret,
    Star,
    Slash,
    Percent,
    Bang,
    Less,
    ModifierOpen, ///< '<' followed by scale, translate or rotate
    Greater,
    LessEqual,
    GreaterEqual,
    EqualEqual,
    NotEqual,
    AndAnd,
    OrOr,
    Question,
    Colon,
    Dot,     ///< '.' before a component's name: `v.x`
    Comment, ///< only reported to a comment observer, never to the parser
};

struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    uint32_t begin = 0;
    uint32_t end = 0;
    bool atLineStart = false; ///< first token on its line
};

/// How a token kind is spelled, for messages ("'->'", "identifier").
std::string_view tokenDescription(TokenKind kind);
bool isKeyword(TokenKind kind);

} // namespace crt::lang
