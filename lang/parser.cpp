// The token source of the Bison parser, its error messages and error recovery.
#include "parser.hpp"

#include "grammar.hpp"
#include "object_schema.hpp"
#include "parser_support.hpp"
#include "povray_habits.hpp"
#include "string_escape.hpp"

#include "large_stack.hpp"

#include <fmt/format.h>

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
    case TokenKind::KwFunction:
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

/// The first node of `item`'s tree nested deeper than `limit`, found without recursion, or
/// null: every walk over the tree (resolver, interpreter, formatter, dumps) recurses.
const Node* tooDeep(Node* item, uint32_t limit) {
    std::vector<std::pair<Node*, uint32_t>> pending{{item, 1}};
    while (!pending.empty()) {
        auto [node, depth] = pending.back();
        pending.pop_back();
        if (depth > limit) return node;
        forEachChild(node, [&, depth = depth](Node* child) { pending.emplace_back(child, depth + 1); });
    }
    return nullptr;
}

/// Replaces each top-level statement that nests deeper than the front end's limit by an error
/// node, after reporting it, so that nothing later walks the too-deep tree.
void limitNesting(ParseContext& ctx) {
    const uint32_t limit = maxNesting();
    for (Node*& item : ctx.items) {
        const Node* deepest = tooDeep(item, limit);
        if (!deepest) continue;
        ctx.diagnostics.error(deepest->range,
                              fmt::format("expressions and blocks nested deeper than {} levels; "
                                          "split this into smaller pieces",
                                          limit));
        item = ctx.node<Node>(NodeKind::Error, item->range);
    }
}

} // namespace

Token ParseContext::skipToResumePoint(Token token) {
    int depth = skipDepth;
    skipDepth = 0;
    for (;; token = lexNext()) {
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
        Escape escape = readEscape(raw, i);
        // A bad escape was reported by the lexer; it decodes to nothing.
        if (escape.error.empty()) appendUtf8(decoded, escape.codePoint);
        i += escape.length - 1;
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

namespace {

/// The next token for the parser: a token put back by error recovery, else the lexer's.
Token takeToken(ParseContext& ctx) {
    if (ctx.queued.empty()) return ctx.nextToken();
    Token token = ctx.queued.front();
    ctx.queued.erase(ctx.queued.begin());
    return token;
}

int64_t integerValue(const Token& token, const Parser::location_type& location, ParseContext& ctx) {
    std::string_view digits = ctx.text(token);
    int64_t value = 0;
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc()) {
        ctx.diagnostics.error(ctx.at(location), "integer literal does not fit in 64 bits; write it "
                                                "as a float");
        return 0;
    }
    return value;
}

double floatValue(const Token& token, const Parser::location_type& location, ParseContext& ctx) {
    double value = 0;
    if (!parseFloat(ctx.text(token), value)) {
        ctx.diagnostics.error(ctx.at(location), "float literal is out of range");
    }
    return value;
}

} // namespace

// One switch from lexer tokens to parser tokens: it is the parser's inner loop, one dispatch
// per token.
int yylex(Parser::semantic_type* value, Parser::location_type* location, ParseContext& ctx) {
    using T = Parser::token;
    if (ctx.recovering) {
        ctx.recovering = false;
        if (ctx.queued.empty()) ctx.queued.push_back(ctx.nextToken());
        uint32_t at = ctx.queued.front().begin;
        *location = {at, at};
        return T::TOK_RECOVERED;
    }
    Token token = takeToken(ctx);
    ctx.previousToken = ctx.lastToken;
    ctx.lastToken = token;
    *location = {token.begin, token.end};
    auto text = [&](std::string_view s) {
        value->text = TextRef{s.data(), static_cast<uint32_t>(s.size())};
    };
    switch (token.kind) {
    case TokenKind::EndOfFile: return T::TOK_END;
    case TokenKind::Identifier: text(ctx.text(token)); return T::TOK_IDENT;
    case TokenKind::Name: text(ctx.text(token)); return T::TOK_NAME;
    case TokenKind::Integer: value->integer = integerValue(token, *location, ctx); return T::TOK_INT;
    case TokenKind::Float: value->number = floatValue(token, *location, ctx); return T::TOK_FLOAT;
    case TokenKind::Invalid: value->number = 0; return T::TOK_FLOAT; // reported by the lexer
    case TokenKind::String: text(ctx.decodeString(token)); return T::TOK_STRING;
    case TokenKind::KwSettings: return T::TOK_SETTINGS;
    case TokenKind::KwScene: return T::TOK_SCENE;
    case TokenKind::KwMacro: return T::TOK_MACRO;
    case TokenKind::KwFunction: return T::TOK_FUNCTION;
    case TokenKind::KwScale: return T::TOK_SCALE;
    case TokenKind::KwTranslate: return T::TOK_TRANSLATE;
    case TokenKind::KwRotate: return T::TOK_ROTATE;
    case TokenKind::KwTrue: return T::TOK_TRUE;
    case TokenKind::KwFalse: return T::TOK_FALSE;
    case TokenKind::KwWhile: return T::TOK_WHILE;
    case TokenKind::KwFor: return T::TOK_FOR;
    case TokenKind::KwIn: return T::TOK_IN;
    case TokenKind::KwIf: return T::TOK_IF;
    case TokenKind::KwElse: return T::TOK_ELSE;
    case TokenKind::KwInclude: return T::TOK_INCLUDE;
    case TokenKind::LParen: return T::TOK_LPAREN;
    case TokenKind::LParenLine: return T::TOK_LPAREN_LINE;
    case TokenKind::RParen: return T::TOK_RPAREN;
    case TokenKind::LBrace: return T::TOK_LBRACE;
    case TokenKind::RBrace: return T::TOK_RBRACE;
    case TokenKind::LBracket: return T::TOK_LBRACKET;
    case TokenKind::LBracketLine: return T::TOK_LBRACKET_LINE;
    case TokenKind::RBracket: return T::TOK_RBRACKET;
    case TokenKind::Comma: return T::TOK_COMMA;
    case TokenKind::Arrow: return T::TOK_ARROW;
    case TokenKind::Assign: return T::TOK_ASSIGN;
    case TokenKind::PlusAssign: return T::TOK_PLUS_ASSIGN;
    case TokenKind::MinusAssign: return T::TOK_MINUS_ASSIGN;
    case TokenKind::StarAssign: return T::TOK_STAR_ASSIGN;
    case TokenKind::SlashAssign: return T::TOK_SLASH_ASSIGN;
    case TokenKind::Plus: return T::TOK_PLUS;
    case TokenKind::Minus: return T::TOK_MINUS;
    case TokenKind::Caret: return T::TOK_CARET;
    case TokenKind::Star: return T::TOK_STAR;
    case TokenKind::Slash: return T::TOK_SLASH;
    case TokenKind::Percent: return T::TOK_PERCENT;
    case TokenKind::Bang: return T::TOK_BANG;
    case TokenKind::Less: return T::TOK_LT;
    case TokenKind::ModifierOpen: return T::TOK_MOD_OPEN;
    case TokenKind::Greater: return T::TOK_GT;
    case TokenKind::LessEqual: return T::TOK_LE;
    case TokenKind::GreaterEqual: return T::TOK_GE;
    case TokenKind::EqualEqual: return T::TOK_EQ;
    case TokenKind::NotEqual: return T::TOK_NE;
    case TokenKind::AndAnd: return T::TOK_AND;
    case TokenKind::OrOr: return T::TOK_OR;
    case TokenKind::Question: return T::TOK_QUESTION;
    case TokenKind::Colon: return T::TOK_COLON;
    case TokenKind::Dot: return T::TOK_DOT;
    case TokenKind::Comment: break;
    }
    return T::TOK_END;
}

void Parser::error(const location_type& where, const std::string& message) {
    // (Here because the entry type is private.) Entries of 32 bytes index with a shift and
    // move as two 16-byte words; a wider location or value would cost every token.
    static_assert(sizeof(stack_symbol_type) == 32, "parser stack entries grew");
    ctx.diagnostics.error(ctx.at(where), message);
}

namespace {

/// The innermost bracket open before `found` (which may open one itself), or null.
const Token* innermostOpenBracket(const ParseContext& ctx, const Token& found) {
    for (auto it = ctx.openBrackets.rbegin(); it != ctx.openBrackets.rend(); ++it)
        if (it->begin != found.begin) return &*it;
    return nullptr;
}

std::string_view closerText(const Token& opener) {
    const TokenKind closer = ParseContext::closerOf(opener.kind);
    return closer == TokenKind::RParen ? ")" : closer == TokenKind::RBrace ? "}" : "]";
}

Parser::symbol_kind_type closerSymbol(const Token& opener) {
    const TokenKind closer = ParseContext::closerOf(opener.kind);
    return closer == TokenKind::RParen   ? Parser::symbol_kind::S_RPAREN
           : closer == TokenKind::RBrace ? Parser::symbol_kind::S_RBRACE
                                         : Parser::symbol_kind::S_RBRACKET;
}

/// Whether `text` ends with `word`, spaces and an unclosed `<x, y, …`.
bool endsWithVectorAfter(std::string_view text, std::string_view word) {
    const size_t open = text.rfind('<');
    if (open == std::string_view::npos || text.find('>', open) != std::string_view::npos)
        return false;
    std::string_view before = text.substr(0, open);
    while (!before.empty() && before.back() == ' ') before.remove_suffix(1);
    return before.ends_with(word);
}

/// What a POV-Ray user may have meant where the parser stopped at `found`: "<x, y, z>" for a
/// vector, "rgb <r, g, b>" for a colour, "i++", a capitalised variable, a bare modifier.
std::string povRayHint(const ParseContext& ctx, const Token& found) {
    const std::string_view text = ctx.file.text();
    const Token& before = ctx.previousToken;
    if (found.kind == TokenKind::Less || found.kind == TokenKind::ModifierOpen) {
        const std::string_view rest = text.substr(found.end);
        const std::string_view inside = rest.substr(0, rest.find_first_of(">\n"));
        if (inside.size() == rest.size() || rest[inside.size()] != '>' ||
            inside.find(',') == std::string_view::npos)
            return "";
        return "; vectors are written vec3(x, y, z), not <x, y, z>";
    }
    if (found.kind == TokenKind::Comma) {
        // `rgb <1, 0, 0>` read as a comparison `rgb < 1`, then the comma.
        const std::string_view line =
            text.substr(0, found.begin).substr(text.rfind('\n', found.begin) + 1);
        if (endsWithVectorAfter(line, "rgb"))
            return "; colours are written rgb(r, g, b), not color rgb <r, g, b>";
    }
    if (found.kind == TokenKind::Assign && before.kind == TokenKind::Name)
        return "; variable names start with a lower-case letter (capitalised names are types)";
    if (before.kind == TokenKind::Plus && before.begin > 0 && text[before.begin - 1] == '+')
        return fmt::format("; {}", povray::kNoIncrement);
    const bool modifier = found.kind == TokenKind::KwTranslate ||
                          found.kind == TokenKind::KwRotate || found.kind == TokenKind::KwScale;
    std::string_view after = text.substr(found.end);
    after.remove_prefix(std::min(after.size(), after.find_first_not_of(" \t")));
    const bool asAttribute = after.starts_with("->");
    if (modifier && !asAttribute)
        return "; modifiers go in angle brackets after what they move: 'thing <translate v>'";
    return "";
}

/// `sphere {`: POV-Ray's lower-case object names; CRT's object types are capitalised. Its other
/// blocks (`light_source {`, `union {` …) get a note saying how CRT writes them.
void povRayBlockNote(const ParseContext& ctx, Diagnostic& d) {
    const Token& name = ctx.previousToken;
    if (name.kind != TokenKind::Identifier) return;
    std::string capitalised(ctx.text(name));
    capitalised[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(capitalised[0])));
    const SourceRange range = ctx.range(name.begin, name.end);
    if (findObjectType(capitalised) == ObjectType::Count) {
        std::string_view hint = povray::blockHint(ctx.text(name));
        if (!hint.empty())
            d.notes.push_back({range, fmt::format("POV-Ray's '{}': {}", ctx.text(name), hint)});
        return;
    }
    d.notes.push_back({range, fmt::format("object types start with a capital letter: '{} {{ … }}'", capitalised)});
    d.fixits.push_back({range, capitalised});
}

/// The object type named before the '{' `opener`, or Count.
ObjectType objectOpenedBy(const ParseContext& ctx, const Token& opener) {
    std::string_view before = ctx.file.text().substr(0, opener.begin);
    while (!before.empty() && (before.back() == ' ' || before.back() == '\t'))
        before.remove_suffix(1);
    size_t start = before.size();
    while (start > 0 && std::isalnum(static_cast<unsigned char>(before[start - 1]))) --start;
    return findObjectType(before.substr(start));
}

/// `name = …` first on its line inside an object opened on an earlier line, `name` being no
/// attribute of it: the object's '}' was forgotten before the line.
bool assignmentAfterUnclosedObject(const ParseContext& ctx, const Token& found,
                                   const Token* opener) {
    const Token& name = ctx.previousToken;
    if (found.kind != TokenKind::Assign || name.kind != TokenKind::Identifier || !name.atLineStart)
        return false;
    if (!opener || opener->kind != TokenKind::LBrace) return false;
    if (ctx.file.lineColumn(opener->begin).line == ctx.file.lineColumn(name.begin).line)
        return false;
    const ObjectType type = objectOpenedBy(ctx, *opener);
    return type == ObjectType::Count || findAttribute(objectInfo(type), ctx.text(name)) < 0;
}

} // namespace

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

    // Ask for every expected token (a statement list allows many), list a few.
    constexpr int kMaxExpected = 8;
    symbol_kind_type expected[YYNTOKENS];
    int count = yyctx.expected_tokens(expected, YYNTOKENS);
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
    const bool listsExpected = count > 0 && count < kMaxExpected && names.size() <= 4;
    if (listsExpected) {
        message += "; expected ";
        for (size_t i = 0; i < names.size(); ++i) {
            if (i > 0) message += i + 1 == names.size() ? " or " : ", ";
            message += symbol_name(names[i]);
            expectsArrow |= names[i] == symbol_kind::S_ARROW;
        }
    }
    // A top-level keyword starting a line where a '}' would do: the '}' was forgotten.
    // Supplying it closes the open block or object, so one mistake is one diagnostic.
    bool topLevelKeyword = found.kind == TokenKind::KwScene || found.kind == TokenKind::KwSettings ||
                           found.kind == TokenKind::KwInclude;
    bool missingBrace = found.begin != ctx.lastResumedAt && found.atLineStart && topLevelKeyword && expectsBrace;
    const Token* opener = innermostOpenBracket(ctx, found);
    const bool objectLeftOpen = assignmentAfterUnclosedObject(ctx, found, opener);
    if (objectLeftOpen) {
        // One error, at the line the '}' should have come before; the object is closed there.
        const Token name = ctx.previousToken;
        if (name.begin != ctx.lastReportedAt) {
            ctx.lastReportedAt = name.begin;
            Diagnostic& d = ctx.diagnostics.error(
                ctx.range(name.begin, found.end),
                fmt::format(
                    "'{} =' cannot stand among the attributes of this '{{'; is a '}}' missing "
                    "before it?",
                    ctx.text(name)));
            d.notes.push_back({ctx.range(opener->begin, opener->end), "the '{' left open"});
        }
        ctx.recovering = true;
        ctx.lastResumedAt = name.begin;
        ctx.queued = {Token{TokenKind::RBrace, name.begin, name.begin, false}, name, found};
        ctx.openBrackets.pop_back(); // the '}' supplied closes it
        ctx.skipping = false;
        return;
    }
    if (found.kind == TokenKind::EndOfFile) {
        // Point at the end of the last line with something on it, not at an empty last line.
        where = ctx.range(ctx.lastTokenEnd, ctx.lastTokenEnd);
        if (opener && std::find(names.begin(), names.end(), closerSymbol(*opener)) != names.end())
            message = fmt::format("unexpected end of file; expected '{}'", closerText(*opener));
    }
    message += povRayHint(ctx, found);
    if (found.begin != ctx.lastReportedAt) {
        ctx.lastReportedAt = found.begin;
        Diagnostic& d = ctx.diagnostics.error(where, std::move(message));
        // "expected ')'" points back at the '(' it would close, as Clang does, when that is on
        // another line.
        const bool expectsCloser = opener && listsExpected &&
                                   std::find(names.begin(), names.end(), closerSymbol(*opener)) != names.end();
        const bool openerElsewhere =
            opener && ctx.file.lineColumn(opener->begin).line != ctx.file.lineColumn(where.begin).line;
        if (openerElsewhere && (expectsCloser || found.kind == TokenKind::EndOfFile))
            d.notes.push_back({ctx.range(opener->begin, opener->end),
                               fmt::format("to match this '{}'", ctx.text(*opener))});
        if (found.kind == TokenKind::LBrace) povRayBlockNote(ctx, d);
        if (expectsArrow && found.kind == TokenKind::Assign) {
            d.message += "; attributes are written 'name -> value'";
            d.fixits.push_back({where, "->"});
        }
        if (missingBrace) {
            d.message += "; is a '}' missing before it?";
            if (opener && opener->kind == TokenKind::LBrace && d.notes.empty())
                d.notes.push_back({ctx.range(opener->begin, opener->end), "the '{' left open"});
        }
    }
    // Skip the rest of the broken statement unless the parser can resume right here (and
    // has not already tried to resume at this very token).
    ctx.recovering = true;
    if (missingBrace) {
        ctx.lastResumedAt = found.begin;
        ctx.queued = {Token{TokenKind::RBrace, found.begin, found.begin, false}, found};
        if (opener && opener->kind == TokenKind::LBrace) {
            // The '}' supplied closes it (the brackets after it are not lexed yet).
            ctx.openBrackets.erase(ctx.openBrackets.begin() + (opener - ctx.openBrackets.data()));
        }
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
    limitNesting(ctx);
    return Script{arena.copy(ctx.items), fileIndex};
}

} // namespace crt::lang
