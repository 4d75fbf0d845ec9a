// The token source of the Bison parser, its error messages and error recovery.
#include "parser.hpp"

#include "grammar.hpp"
#include "parser_support.hpp"

namespace crt::lang {
namespace {

bool canStartStatement(TokenKind kind) {
    switch (kind) {
    case TokenKind::Identifier:
    case TokenKind::Name:
    case TokenKind::Integer:
    case TokenKind::Float:
    case TokenKind::String:
    case TokenKind::KwSettings:
    case TokenKind::KwScene:
    case TokenKind::KwMacro:
    case TokenKind::KwTrue:
    case TokenKind::KwFalse:
    case TokenKind::KwWhile:
    case TokenKind::KwFor:
    case TokenKind::KwIf:
    case TokenKind::KwInclude:
    case TokenKind::LParen:
    case TokenKind::LParenLine:
    case TokenKind::LBracket:
    case TokenKind::LBracketLine:
    case TokenKind::Plus:
    case TokenKind::Minus:
    case TokenKind::Bang: return true;
    default: return false;
    }
}

/// Where the parser may pick up again after an error: a statement that starts a line, a
/// closing brace, or the end of the file.
bool isResumePoint(const Token& token) {
    return token.kind == TokenKind::RBrace || token.kind == TokenKind::EndOfFile ||
           (token.atLineStart && canStartStatement(token.kind));
}

} // namespace

Token ParseContext::nextToken() {
    Token token = lexer.next();
    if (!skipping) return token;
    int depth = skipDepth;
    skipDepth = 0;
    for (;; token = lexer.next()) {
        if (token.kind == TokenKind::EndOfFile) break;
        if (token.kind == TokenKind::LBrace) {
            ++depth;
        } else if (token.kind == TokenKind::RBrace && depth > 0) {
            --depth;
        } else if (depth == 0 && isResumePoint(token)) {
            break;
        }
    }
    skipping = false;
    return token;
}

std::string_view ParseContext::decodeString(const Token& token) {
    std::string_view raw = text(token);
    raw.remove_prefix(1);
    if (!raw.empty() && raw.back() == '"' && token.end - token.begin >= 2) raw.remove_suffix(1);
    if (raw.find('\\') == std::string_view::npos) return raw; // points into the source
    std::string decoded;
    decoded.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 == raw.size()) {
            decoded += raw[i];
            continue;
        }
        switch (raw[++i]) {
        case 'n': decoded += '\n'; break;
        case 't': decoded += '\t'; break;
        case '"': decoded += '"'; break;
        case '\\': decoded += '\\'; break;
        default: break; // already reported by the lexer
        }
    }
    return arena.copy(decoded);
}

namespace {

/// Reads a float literal. Plain decimals of up to 15 significant digits (nearly all in
/// scene files) are exact as an integer divided by a power of ten, one correctly rounded
/// division (Clinger's fast path); anything else goes to std::from_chars.
bool parseFloat(std::string_view text, double& value) {
    static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    uint64_t mantissa = 0;
    int digits = 0;
    int fraction = -1;
    for (char c : text) {
        if (c >= '0' && c <= '9') {
            mantissa = mantissa * 10 + static_cast<uint64_t>(c - '0');
            if (mantissa != 0 && ++digits > 15) break;
            if (fraction >= 0) ++fraction;
        } else if (c == '.' && fraction < 0) {
            fraction = 0;
        } else {
            digits = 99; // an exponent: not the fast path
            break;
        }
    }
    if (digits <= 15 && fraction <= 15) {
        value = static_cast<double>(mantissa) / kPowersOfTen[std::max(fraction, 0)];
        return true;
    }
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range) {
        // Too small to represent is zero, as in C; too large is an error.
        size_t exponent = text.find_first_of("eE");
        std::string_view integerPart = text.substr(0, std::min(text.find('.'), exponent));
        bool underflow = exponent != std::string_view::npos
                             ? text.find('-', exponent) != std::string_view::npos
                             : integerPart.find_first_not_of('0') == std::string_view::npos;
        if (underflow) {
            value = 0.0;
            return true;
        }
    }
    return error == std::errc();
}

} // namespace

namespace grammar {

Parser::symbol_type yylex(ParseContext& ctx) {
    if (ctx.recovering) {
        ctx.recovering = false;
        if (ctx.queued.empty()) ctx.queued.push_back(ctx.nextToken());
        uint32_t at = ctx.queued.front().begin;
        return Parser::make_RECOVERED(ctx.range(at, at));
    }
    Token token;
    if (!ctx.queued.empty()) {
        token = ctx.queued.front();
        ctx.queued.erase(ctx.queued.begin());
    } else {
        token = ctx.nextToken();
    }
    ctx.lastToken = token;
    SourceRange where = ctx.range(token.begin, token.end);
    switch (token.kind) {
    case TokenKind::EndOfFile: return Parser::make_END(where);
    case TokenKind::Identifier: return Parser::make_IDENT(ctx.text(token), where);
    case TokenKind::Name: return Parser::make_NAME(ctx.text(token), where);
    case TokenKind::Integer: {
        std::string_view text = ctx.text(token);
        int64_t value = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc()) {
            ctx.diagnostics.error(where, "integer literal does not fit in 64 bits; write it "
                                         "as a float");
        }
        return Parser::make_INT(value, where);
    }
    case TokenKind::Float: {
        std::string_view text = ctx.text(token);
        double value = 0;
        if (!parseFloat(text, value)) {
            ctx.diagnostics.error(where, "float literal is out of range");
        }
        return Parser::make_FLOAT(value, where);
    }
    case TokenKind::Invalid: return Parser::make_FLOAT(0.0, where); // reported by the lexer
    case TokenKind::String: return Parser::make_STRING(ctx.decodeString(token), where);
    case TokenKind::KwSettings: return Parser::make_SETTINGS(where);
    case TokenKind::KwScene: return Parser::make_SCENE(where);
    case TokenKind::KwMacro: return Parser::make_MACRO(where);
    case TokenKind::KwScale: return Parser::make_SCALE(where);
    case TokenKind::KwTranslate: return Parser::make_TRANSLATE(where);
    case TokenKind::KwRotate: return Parser::make_ROTATE(where);
    case TokenKind::KwTrue: return Parser::make_TRUE(where);
    case TokenKind::KwFalse: return Parser::make_FALSE(where);
    case TokenKind::KwWhile: return Parser::make_WHILE(where);
    case TokenKind::KwFor: return Parser::make_FOR(where);
    case TokenKind::KwIn: return Parser::make_IN(where);
    case TokenKind::KwIf: return Parser::make_IF(where);
    case TokenKind::KwElse: return Parser::make_ELSE(where);
    case TokenKind::KwInclude: return Parser::make_INCLUDE(where);
    case TokenKind::LParen: return Parser::make_LPAREN(where);
    case TokenKind::LParenLine: return Parser::make_LPAREN_LINE(where);
    case TokenKind::RParen: return Parser::make_RPAREN(where);
    case TokenKind::LBrace: return Parser::make_LBRACE(where);
    case TokenKind::RBrace: return Parser::make_RBRACE(where);
    case TokenKind::LBracket: return Parser::make_LBRACKET(where);
    case TokenKind::LBracketLine: return Parser::make_LBRACKET_LINE(where);
    case TokenKind::RBracket: return Parser::make_RBRACKET(where);
    case TokenKind::Comma: return Parser::make_COMMA(where);
    case TokenKind::Arrow: return Parser::make_ARROW(where);
    case TokenKind::Assign: return Parser::make_ASSIGN(where);
    case TokenKind::Plus: return Parser::make_PLUS(where);
    case TokenKind::Minus: return Parser::make_MINUS(where);
    case TokenKind::Caret: return Parser::make_CARET(where);
    case TokenKind::Star: return Parser::make_STAR(where);
    case TokenKind::Slash: return Parser::make_SLASH(where);
    case TokenKind::Percent: return Parser::make_PERCENT(where);
    case TokenKind::Bang: return Parser::make_BANG(where);
    case TokenKind::Less: return Parser::make_LT(where);
    case TokenKind::ModifierOpen: return Parser::make_MOD_OPEN(where);
    case TokenKind::Greater: return Parser::make_GT(where);
    case TokenKind::LessEqual: return Parser::make_LE(where);
    case TokenKind::GreaterEqual: return Parser::make_GE(where);
    case TokenKind::EqualEqual: return Parser::make_EQ(where);
    case TokenKind::NotEqual: return Parser::make_NE(where);
    case TokenKind::AndAnd: return Parser::make_AND(where);
    case TokenKind::OrOr: return Parser::make_OR(where);
    case TokenKind::Question: return Parser::make_QUESTION(where);
    case TokenKind::Colon: return Parser::make_COLON(where);
    case TokenKind::Comment: break;
    }
    return Parser::make_END(where);
}

void Parser::error(const location_type& where, const std::string& message) {
    ctx.diagnostics.error(where, message);
}

void Parser::report_syntax_error(const context& yyctx) const {
    const Token& found = ctx.lastToken;
    SourceRange where = ctx.range(found.begin, found.end);
    std::string foundText;
    switch (found.kind) {
    case TokenKind::Identifier:
    case TokenKind::Name:
    case TokenKind::Integer:
    case TokenKind::Float:
        foundText = fmt::format("{} '{}'", tokenDescription(found.kind), ctx.text(found));
        break;
    default: foundText = std::string(tokenDescription(found.kind)); break;
    }

    constexpr int kMaxExpected = 8;
    symbol_kind_type expected[kMaxExpected];
    int count = yyctx.expected_tokens(expected, kMaxExpected);
    // Line-start brackets are the same character to a reader: name each once.
    std::vector<symbol_kind_type> names;
    for (int i = 0; i < count; ++i) {
        symbol_kind_type kind = expected[i];
        if (kind == symbol_kind::S_LPAREN_LINE) kind = symbol_kind::S_LPAREN;
        if (kind == symbol_kind::S_LBRACKET_LINE) kind = symbol_kind::S_LBRACKET;
        if (std::find(names.begin(), names.end(), kind) == names.end()) names.push_back(kind);
    }
    std::string message = fmt::format("unexpected {}", foundText);
    bool expectsArrow = false;
    bool expectsBrace = std::find(names.begin(), names.end(), symbol_kind::S_RBRACE) != names.end();
    if (count > 0 && count < kMaxExpected && names.size() <= 4) {
        message += "; expected ";
        for (size_t i = 0; i < names.size(); ++i) {
            if (i > 0) message += i + 1 == names.size() ? " or " : ", ";
            message += symbol_name(names[i]);
            expectsArrow |= names[i] == symbol_kind::S_ARROW;
        }
    }
    if (found.begin != ctx.lastReportedAt) {
        ctx.lastReportedAt = found.begin;
        Diagnostic& d = ctx.diagnostics.error(where, std::move(message));
        if (expectsArrow && found.kind == TokenKind::Assign) {
            d.message += "; attributes are written 'name -> value'";
            d.fixits.push_back({where, "->"});
        }
    }
    // Skip the rest of the broken statement unless the parser can resume right here (and
    // has not already tried to resume at this very token).
    ctx.recovering = true;
    // A top-level keyword starting a line where a '}' would do: the '}' was forgotten.
    // Supplying it closes the open block or object, so one mistake is one diagnostic.
    bool topLevelKeyword = found.kind == TokenKind::KwScene || found.kind == TokenKind::KwSettings ||
                           found.kind == TokenKind::KwInclude;
    if (found.begin != ctx.lastResumedAt && found.atLineStart && topLevelKeyword && expectsBrace) {
        ctx.lastResumedAt = found.begin;
        ctx.queued = {Token{TokenKind::RBrace, found.begin, found.begin, false}, found};
        ctx.skipping = false;
    } else if (isResumePoint(found) && found.begin != ctx.lastResumedAt &&
               found.kind != TokenKind::LParenLine && found.kind != TokenKind::LBracketLine) {
        // (A line-start bracket the parser rejects sits inside an unclosed bracket: the
        // rest of that line belongs to the broken statement.)
        ctx.lastResumedAt = found.begin;
        ctx.queued = {found};
        ctx.skipping = false;
    } else {
        ctx.skipping = true;
        ctx.skipDepth = found.kind == TokenKind::LBrace ? 1 : 0;
    }
}

} // namespace grammar

Script parse(const SourceFile& file, uint32_t fileIndex, Arena& arena, DiagnosticBag& diagnostics,
             std::vector<Token>* comments) {
    ParseContext ctx(file, fileIndex, arena, diagnostics);
    ctx.lexer.collectComments(comments);
    grammar::Parser parser(ctx);
    parser.parse();
    return Script{arena.copy(ctx.items), fileIndex};
}

} // namespace crt::lang
