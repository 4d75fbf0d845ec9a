// The re2c lexer for CRT scripts (spec §1). Compiled by re2c into the build tree.
#include "lexer.hpp"

#include "ast.hpp"
#include "povray_habits.hpp"
#include "string_escape.hpp"

#include <fmt/format.h>


namespace crt::lang {

Lexer::Lexer(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics)
    : begin_(file.data()), end_(file.data() + file.size()), cursor_(file.data()),
      fileIndex_(fileIndex), diagnostics_(diagnostics) {
    // Some editors start UTF-8 files with a byte-order mark: it is not part of the script.
    if (file.text().starts_with("\xEF\xBB\xBF")) cursor_ += 3;
}

void Lexer::reportInvalid(const char* start, const char* end) {
    std::string_view text(start, static_cast<size_t>(end - start));
    unsigned char first = static_cast<unsigned char>(text[0]);
    if (text.size() == 1 && first >= 0x80) {
        // Not UTF-8: name the byte rather than copy it into the message.
        diagnostics_.error(range(start, end), fmt::format("invalid UTF-8 byte 0x{:02X}", first));
    } else if (text.size() == 1 && first < 0x20) {
        diagnostics_.error(range(start, end),
                           fmt::format("unexpected character U+{:04X}",
                                       static_cast<unsigned>(static_cast<unsigned char>(text[0]))));
    } else if (text == "_") {
        diagnostics_.error(range(start, end),
                           "unexpected character '_'; names start with a letter");
    } else if (text == ";") {
        diagnostics_.error(range(start, end),
                           "unexpected character ';'; statements need no terminator")
            .fixits.push_back({range(start, end), ""});
    } else {
        diagnostics_.error(range(start, end), fmt::format("unexpected character '{}'", text));
    }
}

Token Lexer::scanString(const char* start) {
    const char* p = start + 1;
    for (;;) {
        char c = *p;
        if (c == '"') {
            return {TokenKind::String, offset(start), offset(p + 1), false};
        }
        if (c == '\n' || c == '\r' || p >= end_) {
            diagnostics_.error(range(start, p), "unterminated string; strings end on their line");
            return {TokenKind::String, offset(start), offset(p), false};
        }
        if (c == '\\') {
            char escaped = p + 1 < end_ ? p[1] : '\0';
            if (escaped == '\n' || escaped == '\r' || p + 1 >= end_) {
                ++p;
                continue; // reported as unterminated on the next turn
            }
            Escape escape = readEscape(std::string_view(p, static_cast<size_t>(end_ - p)), 0);
            if (!escape.error.empty()) {
                diagnostics_.error(range(p, p + escape.length), escape.error);
            }
            p += escape.length;
            continue;
        }
        ++p;
    }
}

/*!re2c
    re2c:api:style = free-form;
    re2c:define:YYCTYPE = "unsigned char";
    re2c:define:YYCURSOR = "cursor";
    re2c:define:YYMARKER = "marker";
    re2c:yyfill:enable = 0;
    re2c:flags:utf-8 = 0;

    digits = [0-9]+;
    exponent = [eE] [+-]? digits;
    float = digits "." [0-9]* exponent? | "." digits exponent? | digits exponent;
    wordtail = [a-zA-Z0-9_]*;
    utf8lead2 = [\xC2-\xDF];
    utf8lead3 = [\xE0-\xEF];
    utf8lead4 = [\xF0-\xF4];
    cont = [\x80-\xBF];
*/

Token Lexer::scan() {
    for (;;) {
        const unsigned char* cursor = reinterpret_cast<const unsigned char*>(cursor_);
        const unsigned char* marker = cursor;
        const char* start = cursor_;
        auto make = [&](TokenKind kind) {
            cursor_ = reinterpret_cast<const char*>(cursor);
            Token token{kind, offset(start), offset(cursor_), lineStart_};
            lineStart_ = false;
            return token;
        };
        (void)marker;
        /*!re2c
        "\x00" {
            if (start >= end_) { cursor_ = end_; return {TokenKind::EndOfFile, offset(end_), offset(end_), lineStart_}; }
            cursor_ = reinterpret_cast<const char*>(cursor);
            reportInvalid(start, cursor_);
            continue;
        }
        "\n" { cursor_ = reinterpret_cast<const char*>(cursor); lineStart_ = true; continue; }
        [ \t\r]+ { cursor_ = reinterpret_cast<const char*>(cursor); continue; }
        "--" {
            // A comment runs to the end of the line, whatever bytes it holds.
            const char* p = reinterpret_cast<const char*>(cursor);
            while (p < end_ && *p != '\n') ++p;
            cursor_ = p;
            if (comments_) comments_->push_back({TokenKind::Comment, offset(start), offset(cursor_), lineStart_});
            continue;
        }

        "Settings"  { return make(TokenKind::KwSettings); }
        "Scene"     { return make(TokenKind::KwScene); }
        "Macro"     { return make(TokenKind::KwMacro); }
        "Function"  { return make(TokenKind::KwFunction); }
        "scale"     { return make(TokenKind::KwScale); }
        "translate" { return make(TokenKind::KwTranslate); }
        "rotate"    { return make(TokenKind::KwRotate); }
        "true"      { return make(TokenKind::KwTrue); }
        "false"     { return make(TokenKind::KwFalse); }
        "while"     { return make(TokenKind::KwWhile); }
        "for"       { return make(TokenKind::KwFor); }
        "in"        { return make(TokenKind::KwIn); }
        "if"        { return make(TokenKind::KwIf); }
        "else"      { return make(TokenKind::KwElse); }
        "include"   { return make(TokenKind::KwInclude); }

        [a-z] wordtail { return make(TokenKind::Identifier); }
        [A-Z] wordtail { return make(TokenKind::Name); }

        float { return make(TokenKind::Float); }
        digits { return make(TokenKind::Integer); }
        (digits ("." [0-9]*)? | "." digits) [eE] [+-]? {
            Token token = make(TokenKind::Invalid);
            diagnostics_.error(range(start, cursor_), "malformed number: the exponent has no digits");
            return token;
        }
        (float | digits) [a-zA-Z_] wordtail {
            Token token = make(TokenKind::Invalid);
            diagnostics_.error(range(start, cursor_),
                fmt::format("malformed number '{}'", std::string_view(start, cursor_ - start)));
            return token;
        }

        ["] { Token token = scanString(start); cursor_ = begin_ + token.end; token.atLineStart = lineStart_; lineStart_ = false; return token; }

        "("  { return make(lineStart_ ? TokenKind::LParenLine : TokenKind::LParen); }
        ")"  { return make(TokenKind::RParen); }
        "{"  { return make(TokenKind::LBrace); }
        "}"  { return make(TokenKind::RBrace); }
        "["  { return make(lineStart_ ? TokenKind::LBracketLine : TokenKind::LBracket); }
        "]"  { return make(TokenKind::RBracket); }
        ","  { return make(TokenKind::Comma); }
        "->" { return make(TokenKind::Arrow); }
        "="  { return make(TokenKind::Assign); }
        "+=" { return make(TokenKind::PlusAssign); }
        "-=" { return make(TokenKind::MinusAssign); }
        "*=" { return make(TokenKind::StarAssign); }
        "/=" { return make(TokenKind::SlashAssign); }
        "+"  { return make(TokenKind::Plus); }
        "-"  { return make(TokenKind::Minus); }
        "^"  { return make(TokenKind::Caret); }
        "*"  { return make(TokenKind::Star); }
        "/"  { return make(TokenKind::Slash); }
        "%"  { return make(TokenKind::Percent); }
        "!"  { return make(TokenKind::Bang); }
        "<"  { return make(TokenKind::Less); }
        ">"  { return make(TokenKind::Greater); }
        "<=" { return make(TokenKind::LessEqual); }
        ">=" { return make(TokenKind::GreaterEqual); }
        "==" { return make(TokenKind::EqualEqual); }
        "!=" { return make(TokenKind::NotEqual); }
        "&&" { return make(TokenKind::AndAnd); }
        "||" { return make(TokenKind::OrOr); }
        "?"  { return make(TokenKind::Question); }
        ":"  { return make(TokenKind::Colon); }
        "."  { return make(TokenKind::Dot); }

        "#" [a-z]+ {
            // POV-Ray's directives (#declare x = 1, #include "f.inc", #macro …): one error
            // saying how CRT writes it, and the line skipped where it is no CRT.
            const std::string_view word(start + 1, reinterpret_cast<const char*>(cursor) - start - 1);
            std::string message = "unexpected character '#'; CRT has no '#' directives";
            if (std::string_view how = povray::directiveHint(word); !how.empty()) message += fmt::format(": {}", how);
            diagnostics_.error(range(start, start + 1), std::move(message));
            const char* p = reinterpret_cast<const char*>(cursor);
            if (povray::directiveLineIsForeign(word))
                while (p < end_ && *p != '\n') ++p;
            cursor_ = p;
            continue;
        }
        utf8lead2 cont | utf8lead3 cont cont | utf8lead4 cont cont cont | [^] {
            cursor_ = reinterpret_cast<const char*>(cursor);
            reportInvalid(start, cursor_);
            continue;
        }
        */
    }
}

namespace {

bool isModifierKeyword(TokenKind kind) {
    return kind == TokenKind::KwScale || kind == TokenKind::KwTranslate || kind == TokenKind::KwRotate;
}

/// The modifiers that are words rather than keywords (they name attributes elsewhere).
bool isNamedModifier(std::string_view word) { return namedModifier(word).has_value(); }

/// Whether a token can begin a named modifier's operand (`material m`, `shadow false`).
bool startsOperand(TokenKind kind) {
    return kind == TokenKind::Identifier || kind == TokenKind::Name || kind == TokenKind::Integer ||
           kind == TokenKind::Float || kind == TokenKind::LBracket || kind == TokenKind::LParen ||
           kind == TokenKind::KwTrue || kind == TokenKind::KwFalse;
}

} // namespace

void Lexer::classifyLess(Token& less) {
    const Token& first = peek(0);
    bool opens = isModifierKeyword(first.kind);
    if (!opens && first.kind == TokenKind::Identifier) {
        const std::string_view word = text(first);
        const TokenKind after = peek(1).kind;
        opens = (isNamedModifier(word) && startsOperand(after)) || after == TokenKind::Greater ||
                (after == TokenKind::Comma && (isModifierKeyword(peek(2).kind) ||
                                               (peek(2).kind == TokenKind::Identifier && isNamedModifier(text(peek(2))))));
    }
    if (opens) less.kind = TokenKind::ModifierOpen;
}

std::vector<Token> lexAll(const SourceFile& file, uint32_t fileIndex, DiagnosticBag& diagnostics,
                          std::vector<Token>* comments) {
    Lexer lexer(file, fileIndex, diagnostics);
    lexer.collectComments(comments);
    std::vector<Token> tokens;
    for (Token token = lexer.next(); token.kind != TokenKind::EndOfFile; token = lexer.next()) {
        tokens.push_back(token);
    }
    return tokens;
}

std::string_view tokenDescription(TokenKind kind) {
    switch (kind) {
    case TokenKind::EndOfFile: return "end of file";
    case TokenKind::Invalid: return "invalid token";
    case TokenKind::Identifier: return "identifier";
    case TokenKind::Name: return "type name";
    case TokenKind::Integer: return "integer";
    case TokenKind::Float: return "float";
    case TokenKind::String: return "string";
    case TokenKind::KwSettings: return "'Settings'";
    case TokenKind::KwScene: return "'Scene'";
    case TokenKind::KwMacro: return "'Macro'";
    case TokenKind::KwFunction: return "'Function'";
    case TokenKind::KwScale: return "'scale'";
    case TokenKind::KwTranslate: return "'translate'";
    case TokenKind::KwRotate: return "'rotate'";
    case TokenKind::KwTrue: return "'true'";
    case TokenKind::KwFalse: return "'false'";
    case TokenKind::KwWhile: return "'while'";
    case TokenKind::KwFor: return "'for'";
    case TokenKind::KwIn: return "'in'";
    case TokenKind::KwIf: return "'if'";
    case TokenKind::KwElse: return "'else'";
    case TokenKind::KwInclude: return "'include'";
    case TokenKind::LParen:
    case TokenKind::LParenLine: return "'('";
    case TokenKind::RParen: return "')'";
    case TokenKind::LBrace: return "'{'";
    case TokenKind::RBrace: return "'}'";
    case TokenKind::LBracket:
    case TokenKind::LBracketLine: return "'['";
    case TokenKind::RBracket: return "']'";
    case TokenKind::Comma: return "','";
    case TokenKind::Arrow: return "'->'";
    case TokenKind::Assign: return "'='";
    case TokenKind::PlusAssign: return "'+='";
    case TokenKind::MinusAssign: return "'-='";
    case TokenKind::StarAssign: return "'*='";
    case TokenKind::SlashAssign: return "'/='";
    case TokenKind::Plus: return "'+'";
    case TokenKind::Minus: return "'-'";
    case TokenKind::Caret: return "'^'";
    case TokenKind::Star: return "'*'";
    case TokenKind::Slash: return "'/'";
    case TokenKind::Percent: return "'%'";
    case TokenKind::Bang: return "'!'";
    case TokenKind::Less: return "'<'";
    case TokenKind::ModifierOpen: return "'<'";
    case TokenKind::Greater: return "'>'";
    case TokenKind::LessEqual: return "'<='";
    case TokenKind::GreaterEqual: return "'>='";
    case TokenKind::EqualEqual: return "'=='";
    case TokenKind::NotEqual: return "'!='";
    case TokenKind::AndAnd: return "'&&'";
    case TokenKind::OrOr: return "'||'";
    case TokenKind::Question: return "'?'";
    case TokenKind::Colon: return "':'";
    case TokenKind::Dot: return "'.'";
    case TokenKind::Comment: return "comment";
    }
    return "token";
}

bool isKeyword(TokenKind kind) {
    return kind >= TokenKind::KwSettings && kind <= TokenKind::KwInclude;
}

} // namespace crt::lang
