// The lexer (spec §1): every token kind, comments, the two context rules, ranges, error recovery.
#include <catch2/catch.hpp>

#include "lexer.hpp"

#include <string>
#include <vector>

using namespace crt::lang;

namespace {

struct Lexed {
    std::vector<Token> tokens;
    std::vector<Token> comments;
    std::vector<Diagnostic> diagnostics;
    std::string text;

    std::vector<TokenKind> kinds() const {
        std::vector<TokenKind> result;
        for (const Token& t : tokens) result.push_back(t.kind);
        return result;
    }
    std::string textOf(const Token& t) const { return text.substr(t.begin, t.end - t.begin); }
    std::vector<std::string> texts() const {
        std::vector<std::string> result;
        for (const Token& t : tokens) result.push_back(textOf(t));
        return result;
    }
};

Lexed lex(const std::string& text) {
    SourceFile file("t.crt", text);
    DiagnosticBag bag;
    Lexed result;
    result.text = text;
    result.tokens = lexAll(file, 3, bag, &result.comments);
    result.diagnostics = bag.items();
    return result;
}

/// The kind of the only token of `text`, which must lex without diagnostics.
TokenKind single(const std::string& text) {
    Lexed l = lex(text);
    INFO("text: " << text);
    REQUIRE(l.diagnostics.empty());
    REQUIRE(l.tokens.size() == 1);
    CHECK(l.tokens[0].begin == 0);
    CHECK(l.tokens[0].end == text.size());
    return l.tokens[0].kind;
}

SourceRange at(uint32_t begin, uint32_t end) { return {3, begin, end}; }

using K = TokenKind;

} // namespace

TEST_CASE("lexer: every keyword") {
    CHECK(single("Settings") == K::KwSettings);
    CHECK(single("Scene") == K::KwScene);
    CHECK(single("Macro") == K::KwMacro);
    CHECK(single("scale") == K::KwScale);
    CHECK(single("translate") == K::KwTranslate);
    CHECK(single("rotate") == K::KwRotate);
    CHECK(single("true") == K::KwTrue);
    CHECK(single("false") == K::KwFalse);
    CHECK(single("while") == K::KwWhile);
    CHECK(single("for") == K::KwFor);
    CHECK(single("in") == K::KwIn);
    CHECK(single("if") == K::KwIf);
    CHECK(single("else") == K::KwElse);
    CHECK(single("include") == K::KwInclude);
    CHECK(isKeyword(K::KwSettings));
    CHECK(isKeyword(K::KwInclude));
    CHECK_FALSE(isKeyword(K::Identifier));
}

TEST_CASE("lexer: words that only resemble keywords are identifiers or names") {
    CHECK(single("scales") == K::Identifier);
    CHECK(single("inside") == K::Identifier);
    CHECK(single("iff") == K::Identifier);
    CHECK(single("true_") == K::Identifier);
    CHECK(single("Scenes") == K::Name);
    CHECK(single("If") == K::Name);
    CHECK(single("SETTINGS") == K::Name);
    CHECK(single("Macro2") == K::Name);
}

TEST_CASE("lexer: identifiers start lower-case, names upper-case") {
    CHECK(single("x") == K::Identifier);
    CHECK(single("radius") == K::Identifier);
    CHECK(single("camelCase9") == K::Identifier);
    CHECK(single("snake_case_") == K::Identifier);
    CHECK(single("S") == K::Name);
    CHECK(single("Sphere") == K::Name);
    CHECK(single("My_Type2") == K::Name);
    Lexed l = lex("abc Def g_1 H_2");
    CHECK(l.kinds() == std::vector<K>{K::Identifier, K::Name, K::Identifier, K::Name});
    CHECK(l.texts() == std::vector<std::string>{"abc", "Def", "g_1", "H_2"});
}

TEST_CASE("lexer: integers") {
    CHECK(single("0") == K::Integer);
    CHECK(single("42") == K::Integer);
    CHECK(single("007") == K::Integer);
    // Too large for 64 bits is still an integer token; the parser reports it.
    CHECK(single("99999999999999999999999") == K::Integer);
}

TEST_CASE("lexer: every float form") {
    CHECK(single("1.5") == K::Float);
    CHECK(single("1.") == K::Float);
    CHECK(single("0.0") == K::Float);
    CHECK(single(".5") == K::Float);
    CHECK(single("1.5e3") == K::Float);
    CHECK(single("1.e3") == K::Float);
    CHECK(single("1.5E-3") == K::Float);
    CHECK(single("1.5e+3") == K::Float);
    CHECK(single(".5e2") == K::Float);
    CHECK(single(".5E+2") == K::Float);
    CHECK(single(".5e-2") == K::Float);
    CHECK(single("1e3") == K::Float);
    CHECK(single("1E3") == K::Float);
    CHECK(single("1e+3") == K::Float);
    CHECK(single("1e-3") == K::Float);
    CHECK(single("12e007") == K::Float);
}

TEST_CASE("lexer: a float is not followed by a second dot") {
    Lexed l = lex("1.2.3");
    CHECK(l.diagnostics.empty());
    CHECK(l.kinds() == std::vector<K>{K::Float, K::Float});
    CHECK(l.texts() == std::vector<std::string>{"1.2", ".3"});
}

TEST_CASE("lexer: a dot after a name reads a component; a dot before digits starts a float") {
    Lexed l = lex("v.x v .5 (v).z");
    CHECK(l.diagnostics.empty());
    CHECK(l.kinds() == std::vector<K>{K::Identifier, K::Dot, K::Identifier, K::Identifier, K::Float,
                                      K::LParen, K::Identifier, K::RParen, K::Dot, K::Identifier});
}

TEST_CASE("lexer: strings with every escape") {
    CHECK(single(R"("")") == K::String);
    CHECK(single(R"("sky.jpg")") == K::String);
    CHECK(single(R"("a \"quoted\" word")") == K::String);
    CHECK(single(R"("back\\slash")") == K::String);
    CHECK(single(R"("line\nbreak")") == K::String);
    CHECK(single(R"("tab\tstop")") == K::String);
    CHECK(single(R"("\\")") == K::String);
    CHECK(single(R"("\"")") == K::String);
    CHECK(single("\"é€𝄞 and -- not a comment\"") == K::String);
}

TEST_CASE("lexer: a string ends at its closing quote") {
    Lexed l = lex(R"("a\\" b "c")");
    CHECK(l.diagnostics.empty());
    CHECK(l.kinds() == std::vector<K>{K::String, K::Identifier, K::String});
    CHECK(l.texts() == std::vector<std::string>{R"("a\\")", "b", R"("c")"});
}

TEST_CASE("lexer: every punctuation token") {
    CHECK(single(")") == K::RParen);
    CHECK(single("{") == K::LBrace);
    CHECK(single("}") == K::RBrace);
    CHECK(single("]") == K::RBracket);
    CHECK(single(",") == K::Comma);
    CHECK(single("->") == K::Arrow);
    CHECK(single("=") == K::Assign);
    CHECK(single("+") == K::Plus);
    CHECK(single("-") == K::Minus);
    CHECK(single("^") == K::Caret);
    CHECK(single("*") == K::Star);
    CHECK(single("/") == K::Slash);
    CHECK(single("%") == K::Percent);
    CHECK(single("!") == K::Bang);
    CHECK(single("<") == K::Less);
    CHECK(single(">") == K::Greater);
    CHECK(single("<=") == K::LessEqual);
    CHECK(single(">=") == K::GreaterEqual);
    CHECK(single("==") == K::EqualEqual);
    CHECK(single("!=") == K::NotEqual);
    CHECK(single("&&") == K::AndAnd);
    CHECK(single("||") == K::OrOr);
    CHECK(single("?") == K::Question);
    CHECK(single(":") == K::Colon);
    CHECK(single(".") == K::Dot);
    // '(' and '[' first in the file are at a line start.
    CHECK(single("(") == K::LParenLine);
    CHECK(single("[") == K::LBracketLine);
    CHECK(lex("x (").kinds().back() == K::LParen);
    CHECK(lex("x [").kinds().back() == K::LBracket);
}

TEST_CASE("lexer: punctuation is split by longest match") {
    Lexed l = lex("a->b>=c<=d==e!=f&&g||h");
    CHECK(l.diagnostics.empty());
    CHECK(l.kinds() == std::vector<K>{K::Identifier, K::Arrow, K::Identifier, K::GreaterEqual,
                                      K::Identifier, K::LessEqual, K::Identifier, K::EqualEqual,
                                      K::Identifier, K::NotEqual, K::Identifier, K::AndAnd,
                                      K::Identifier, K::OrOr, K::Identifier});
    // There is no '>>' token, and '=>', '- >' and '!!' are two tokens each.
    CHECK(lex(">>").kinds() == std::vector<K>{K::Greater, K::Greater});
    CHECK(lex("=>").kinds() == std::vector<K>{K::Assign, K::Greater});
    CHECK(lex("- >").kinds() == std::vector<K>{K::Minus, K::Greater});
    CHECK(lex("!!").kinds() == std::vector<K>{K::Bang, K::Bang});
    CHECK(lex("===").kinds() == std::vector<K>{K::EqualEqual, K::Assign});
    CHECK(lex("a-1").kinds() == std::vector<K>{K::Identifier, K::Minus, K::Integer});
}

TEST_CASE("lexer: whitespace is space, tab, CR and LF") {
    Lexed l = lex(" \t a\r\n\tb \r c\n");
    CHECK(l.diagnostics.empty());
    CHECK(l.texts() == std::vector<std::string>{"a", "b", "c"});
}

TEST_CASE("lexer: '--' starts a comment to the end of the line, always") {
    Lexed l = lex("5--1");
    CHECK(l.diagnostics.empty());
    REQUIRE(l.tokens.size() == 1);
    CHECK(l.tokens[0].kind == K::Integer);
    CHECK(l.tokens[0].end == 1);
    REQUIRE(l.comments.size() == 1);
    CHECK(l.comments[0].kind == K::Comment);
    CHECK(l.comments[0].begin == 1);
    CHECK(l.comments[0].end == 4);

    Lexed m = lex("x = 2 -- three\ny -- \"not a string\n---\nz");
    CHECK(m.diagnostics.empty());
    CHECK(m.texts() == std::vector<std::string>{"x", "=", "2", "y", "z"});
    REQUIRE(m.comments.size() == 3);
    CHECK(m.textOf(m.comments[0]) == "-- three");
    CHECK(m.textOf(m.comments[1]) == "-- \"not a string");
    CHECK(m.textOf(m.comments[2]) == "---");
    for (const Token& c : m.comments) CHECK(c.kind == K::Comment);
}

TEST_CASE("lexer: comments are only reported to the collector") {
    SourceFile file("c.crt", "-- only a comment\n-- and another");
    DiagnosticBag bag;
    std::vector<Token> comments;
    std::vector<Token> tokens = lexAll(file, 0, bag, &comments);
    CHECK(tokens.empty());
    CHECK(bag.items().empty());
    REQUIRE(comments.size() == 2);
    CHECK(comments[0].begin == 0);
    CHECK(comments[0].end == 17);
    CHECK(comments[1].begin == 18);
    CHECK(comments[1].end == 32);
    // Without a collector nothing breaks.
    CHECK(lexAll(file, 0, bag).empty());
}

TEST_CASE("lexer: a comment hides everything up to the line end") {
    // Spec §1: '--' to the end of the line, always; a stray NUL byte in a comment must not
    // end it.
    Lexed l = lex(std::string("-- note\0 a b\nz", 14));
    CHECK(l.texts() == std::vector<std::string>{"z"});
}

TEST_CASE("lexer: the last token is followed by EndOfFile forever") {
    SourceFile file("e.crt", "a ");
    DiagnosticBag bag;
    Lexer lexer(file, 0, bag);
    Token a = lexer.next();
    CHECK(a.kind == K::Identifier);
    for (int i = 0; i < 3; ++i) {
        Token end = lexer.next();
        CHECK(end.kind == K::EndOfFile);
        CHECK(end.begin == 2);
        CHECK(end.end == 2);
    }
}

TEST_CASE("lexer: a paren or bracket first on its line cannot be a call or an index") {
    CHECK(lex("f (x)").kinds().at(1) == K::LParen);
    CHECK(lex("f(x)").kinds().at(1) == K::LParen);
    CHECK(lex("f\n(x)").kinds().at(1) == K::LParenLine);
    CHECK(lex("f\n   \t(x)").kinds().at(1) == K::LParenLine);
    CHECK(lex("f\r\n(x)").kinds().at(1) == K::LParenLine);
    CHECK(lex("l [0]").kinds().at(1) == K::LBracket);
    CHECK(lex("l\n[0]").kinds().at(1) == K::LBracketLine);
    CHECK(lex("l\n  [0]").kinds().at(1) == K::LBracketLine);
    // Only the first token of a line: a second bracket on it is an ordinary one.
    CHECK(lex("\n((x))").kinds() ==
          std::vector<K>{K::LParenLine, K::LParen, K::Identifier, K::RParen, K::RParen});
    CHECK(lex("\n[[1]]").kinds() ==
          std::vector<K>{K::LBracketLine, K::LBracket, K::Integer, K::RBracket, K::RBracket});
}

TEST_CASE("lexer: a comment does not stop a bracket from being first on its line") {
    CHECK(lex("f\n-- a comment\n(x)").kinds().at(1) == K::LParenLine);
    CHECK(lex("f -- trailing comment\n(x)").kinds().at(1) == K::LParenLine);
    CHECK(lex("l\n-- one\n\n  -- two\n[0]").kinds().at(1) == K::LBracketLine);
    CHECK(lex("-- header\n(x)").kinds().at(0) == K::LParenLine);
}

TEST_CASE("lexer: atLineStart marks the first token of every line") {
    Lexed l = lex("a b\n  c -- x\n-- y\nd e\n\"s\" f");
    REQUIRE(l.tokens.size() == 7);
    std::vector<bool> starts;
    for (const Token& t : l.tokens) starts.push_back(t.atLineStart);
    CHECK(starts == std::vector<bool>{true, false, true, true, false, true, false});
}

TEST_CASE("lexer: '<' before scale, translate or rotate opens modifiers") {
    CHECK(lex("a <scale 2>").kinds().at(1) == K::ModifierOpen);
    CHECK(lex("a<translate v>").kinds().at(1) == K::ModifierOpen);
    CHECK(lex("a <rotate v>").kinds().at(1) == K::ModifierOpen);
    CHECK(lex("a <\n  scale 2>").kinds().at(1) == K::ModifierOpen);
    CHECK(lex("a < -- why not\n rotate v>").kinds().at(1) == K::ModifierOpen);
    // The token after the opener keeps its own kind and range.
    Lexed l = lex("a < -- c\n scale 2>");
    REQUIRE(l.tokens.size() == 5);
    CHECK(l.tokens[1].begin == 2);
    CHECK(l.tokens[1].end == 3);
    CHECK(l.tokens[2].kind == K::KwScale);
    CHECK(l.textOf(l.tokens[2]) == "scale");
    CHECK(l.comments.size() == 1);
}

TEST_CASE("lexer: any other '<' is less-than") {
    CHECK(lex("a < b").kinds().at(1) == K::Less);
    CHECK(lex("a < scales").kinds().at(1) == K::Less);
    CHECK(lex("a < Scale").kinds().at(1) == K::Less);
    CHECK(lex("a < 1").kinds().at(1) == K::Less);
    CHECK(lex("a <").kinds().at(1) == K::Less);
    CHECK(lex("a <= scale").kinds().at(1) == K::LessEqual);
    CHECK(lex("a < (scale)").kinds().at(1) == K::Less);
}

TEST_CASE("lexer: a '<' directly after another '<' is still decided by its next token") {
    // The lookahead token of the first '<' is itself a '<' followed by 'scale'.
    CHECK(lex("a < <scale 2>").kinds() ==
          std::vector<K>{K::Identifier, K::Less, K::ModifierOpen, K::KwScale, K::Integer,
                         K::Greater});
}

TEST_CASE("lexer: token byte ranges are exact") {
    std::string text = "ab = 12.5 -> \"s\\n\"\n  Box<scale 2>";
    Lexed l = lex(text);
    CHECK(l.diagnostics.empty());
    struct Expected {
        K kind;
        uint32_t begin, end;
    };
    std::vector<Expected> expected = {
        {K::Identifier, 0, 2}, {K::Assign, 3, 4},       {K::Float, 5, 9},
        {K::Arrow, 10, 12},    {K::String, 13, 18},     {K::Name, 21, 24},
        {K::ModifierOpen, 24, 25}, {K::KwScale, 25, 30}, {K::Integer, 31, 32},
        {K::Greater, 32, 33},
    };
    REQUIRE(l.tokens.size() == expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        INFO("token " << i);
        CHECK(l.tokens[i].kind == expected[i].kind);
        CHECK(l.tokens[i].begin == expected[i].begin);
        CHECK(l.tokens[i].end == expected[i].end);
    }
}

TEST_CASE("lexer: ranges after multi-byte text count bytes") {
    Lexed l = lex("\"é€𝄞\" x");
    CHECK(l.diagnostics.empty());
    REQUIRE(l.tokens.size() == 2);
    CHECK(l.tokens[0].end == 11); // quote + 2 + 3 + 4 bytes + quote
    CHECK(l.tokens[1].begin == 12);
    CHECK(l.tokens[1].end == 13);
}

TEST_CASE("lexer: a bad character is one error, and lexing goes on") {
    for (std::string bad : {"@", "#", "$", "&", "|", "~", "`", "'", "\\"}) {
        INFO("character " << bad);
        Lexed l = lex("a " + bad + " b");
        REQUIRE(l.diagnostics.size() == 1);
        CHECK(l.diagnostics[0].severity == Severity::Error);
        CHECK(l.diagnostics[0].range == at(2, 3));
        CHECK(l.texts() == std::vector<std::string>{"a", "b"});
    }
}

TEST_CASE("lexer: semicolon and underscore get specific messages") {
    Lexed semi = lex("x = 1;\ny");
    REQUIRE(semi.diagnostics.size() == 1);
    CHECK(semi.diagnostics[0].range == at(5, 6));
    CHECK(semi.diagnostics[0].message.find("';'") != std::string::npos);
    REQUIRE(semi.diagnostics[0].fixits.size() == 1);
    CHECK(semi.diagnostics[0].fixits[0].replacement.empty());
    CHECK(semi.texts() == std::vector<std::string>{"x", "=", "1", "y"});

    Lexed under = lex("_x");
    REQUIRE(under.diagnostics.size() == 1);
    CHECK(under.diagnostics[0].range == at(0, 1));
    CHECK(under.texts() == std::vector<std::string>{"x"});
}

TEST_CASE("lexer: control characters and NUL are errors at their byte") {
    Lexed ctrl = lex("a\x01 b");
    REQUIRE(ctrl.diagnostics.size() == 1);
    CHECK(ctrl.diagnostics[0].range == at(1, 2));
    CHECK(ctrl.diagnostics[0].message.find("U+0001") != std::string::npos);
    CHECK(ctrl.texts() == std::vector<std::string>{"a", "b"});

    Lexed nul = lex(std::string("a\0b", 3));
    REQUIRE(nul.diagnostics.size() == 1);
    CHECK(nul.diagnostics[0].range == at(1, 2));
    CHECK(nul.texts() == std::vector<std::string>{"a", "b"});
}

TEST_CASE("lexer: an unterminated string is one error, and the next line lexes") {
    Lexed l = lex("s = \"abc\nx = 1");
    REQUIRE(l.diagnostics.size() == 1);
    CHECK(l.diagnostics[0].range == at(4, 8));
    CHECK(l.kinds() ==
          std::vector<K>{K::Identifier, K::Assign, K::String, K::Identifier, K::Assign, K::Integer});
    CHECK(l.tokens[2].begin == 4);
    CHECK(l.tokens[2].end == 8);
    CHECK(l.tokens[3].atLineStart);

    Lexed eof = lex("\"abc");
    REQUIRE(eof.diagnostics.size() == 1);
    CHECK(eof.diagnostics[0].range == at(0, 4));
    REQUIRE(eof.tokens.size() == 1);
    CHECK(eof.tokens[0].kind == K::String);

    // A backslash at the end of the line does not escape the line break.
    Lexed slash = lex("\"abc\\\ny");
    REQUIRE(slash.diagnostics.size() == 1);
    CHECK(slash.diagnostics[0].range == at(0, 5));
    CHECK(slash.texts().back() == "y");
}

TEST_CASE("lexer: a bad escape is one error at the escape, and the string goes on") {
    Lexed l = lex(R"("a\qb" x)");
    REQUIRE(l.diagnostics.size() == 1);
    CHECK(l.diagnostics[0].range == at(2, 4));
    CHECK(l.diagnostics[0].message.find("\\q") != std::string::npos);
    CHECK(l.kinds() == std::vector<K>{K::String, K::Identifier});
    CHECK(l.tokens[0].end == 6);

    // Two bad escapes, two errors; a multi-byte character after '\' is one escape.
    Lexed two = lex("\"\\x\\é\"");
    REQUIRE(two.diagnostics.size() == 2);
    CHECK(two.diagnostics[0].range == at(1, 3));
    CHECK(two.diagnostics[1].range == at(3, 6));
    CHECK(two.tokens.size() == 1);
}

TEST_CASE("lexer: an exponent without digits is one error") {
    Lexed a = lex("1e x");
    REQUIRE(a.diagnostics.size() == 1);
    CHECK(a.diagnostics[0].range == at(0, 2));
    CHECK(a.kinds() == std::vector<K>{K::Invalid, K::Identifier});

    Lexed b = lex("1.5e+ x");
    REQUIRE(b.diagnostics.size() == 1);
    CHECK(b.diagnostics[0].range == at(0, 5));
    CHECK(b.kinds() == std::vector<K>{K::Invalid, K::Identifier});

    Lexed c = lex(".5E- 2");
    REQUIRE(c.diagnostics.size() == 1);
    CHECK(c.diagnostics[0].range == at(0, 4));
    CHECK(c.kinds() == std::vector<K>{K::Invalid, K::Integer});
}

TEST_CASE("lexer: a number running into letters is one error") {
    Lexed a = lex("12abc + y");
    REQUIRE(a.diagnostics.size() == 1);
    CHECK(a.diagnostics[0].range == at(0, 5));
    CHECK(a.diagnostics[0].message.find("12abc") != std::string::npos);
    CHECK(a.kinds() == std::vector<K>{K::Invalid, K::Plus, K::Identifier});

    Lexed b = lex("1.5x2 3");
    REQUIRE(b.diagnostics.size() == 1);
    CHECK(b.diagnostics[0].range == at(0, 5));
    CHECK(b.kinds() == std::vector<K>{K::Invalid, K::Integer});

    Lexed c = lex("1e5_ 3");
    REQUIRE(c.diagnostics.size() == 1);
    CHECK(c.diagnostics[0].range == at(0, 4));
    CHECK(c.kinds() == std::vector<K>{K::Invalid, K::Integer});
}

TEST_CASE("lexer: several errors on one line are each reported") {
    Lexed l = lex("a @ 1e \"x\\q\" 12ab # b");
    REQUIRE(l.diagnostics.size() == 5);
    CHECK(l.diagnostics[0].range == at(2, 3));
    CHECK(l.diagnostics[1].range == at(4, 6));
    CHECK(l.diagnostics[2].range == at(9, 11));
    CHECK(l.diagnostics[3].range == at(13, 17));
    CHECK(l.diagnostics[4].range == at(18, 19));
    CHECK(l.kinds() == std::vector<K>{K::Identifier, K::Invalid, K::String, K::Invalid, K::Identifier});
}

TEST_CASE("lexer: non-ASCII outside strings is one error per code point") {
    Lexed l = lex("é€𝄞 x");
    REQUIRE(l.diagnostics.size() == 3);
    CHECK(l.diagnostics[0].range == at(0, 2));
    CHECK(l.diagnostics[1].range == at(2, 5));
    CHECK(l.diagnostics[2].range == at(5, 9));
    CHECK(l.diagnostics[1].message.find("€") != std::string::npos);
    CHECK(l.texts() == std::vector<std::string>{"x"});

    // Inside a word: the letters before and after still form tokens.
    Lexed w = lex("caf\xC3\xA9s");
    REQUIRE(w.diagnostics.size() == 1);
    CHECK(w.diagnostics[0].range == at(3, 5));
    CHECK(w.texts() == std::vector<std::string>{"caf", "s"});
}

TEST_CASE("lexer: invalid UTF-8 bytes are one error each") {
    Lexed l = lex("\xFF\xC3 x \x80");
    REQUIRE(l.diagnostics.size() == 3);
    CHECK(l.diagnostics[0].range == at(0, 1));
    CHECK(l.diagnostics[1].range == at(1, 2));
    CHECK(l.diagnostics[2].range == at(5, 6));
    CHECK(l.texts() == std::vector<std::string>{"x"});
}

TEST_CASE("lexer: diagnostics carry the file index") {
    SourceFile file("i.crt", "@");
    DiagnosticBag bag;
    lexAll(file, 7, bag);
    REQUIRE(bag.items().size() == 1);
    CHECK(bag.items()[0].range.file == 7);
}

TEST_CASE("lexer: token descriptions for messages") {
    CHECK(tokenDescription(K::Arrow) == "'->'");
    CHECK(tokenDescription(K::LParenLine) == tokenDescription(K::LParen));
    CHECK(tokenDescription(K::ModifierOpen) == tokenDescription(K::Less));
    CHECK(tokenDescription(K::Identifier) == "identifier");
    CHECK(tokenDescription(K::EndOfFile) == "end of file");
}
