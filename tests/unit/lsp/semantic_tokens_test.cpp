// Semantic tokens on valid and broken scripts.
#include "annotations.hpp"
#include "semantic_tokens.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;

namespace {

/// The token type and modifiers at `range`, or fails.
std::pair<TokenType, uint32_t> tokenAt(const std::vector<SemanticToken>& tokens, crt::lang::SourceRange range) {
    for (const SemanticToken& t : tokens) {
        if (t.range.begin == range.begin && t.range.end == range.end) return {t.type, t.modifiers};
    }
    FAIL("no token at " << range.begin << ".." << range.end);
    return {};
}

} // namespace

TEST_CASE("semantic tokens classify keywords, types, attributes, names and literals", "[semantic]") {
    Annotations code(R"($kw«Settings» { $attr«width» -> $num«800» }
$mdef«grow» = $kw2«Macro» ($pdef«r») {
    $type«Sphere» { center -> $fn«vec3»(0, 0, 0) radius -> $param«r» * $num2«1.5» }
}
$comment«-- a comment»
$str«"text"»
Scene { $macro«grow»($t«t») $op«+» grow(1) }
)");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("kw")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("kw2")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("attr")).first == TokenType::Property);
    CHECK(tokenAt(tokens, code.range("num")).first == TokenType::Number);
    CHECK(tokenAt(tokens, code.range("num2")).first == TokenType::Number);
    CHECK(tokenAt(tokens, code.range("mdef")) == std::pair{TokenType::Macro, uint32_t{ModDeclaration | ModDefinition}});
    CHECK(tokenAt(tokens, code.range("macro")) == std::pair{TokenType::Macro, uint32_t{0}});
    CHECK(tokenAt(tokens, code.range("pdef")) == std::pair{TokenType::Parameter, uint32_t{ModDeclaration | ModDefinition}});
    CHECK(tokenAt(tokens, code.range("param")) == std::pair{TokenType::Parameter, uint32_t{0}});
    CHECK(tokenAt(tokens, code.range("type")) == std::pair{TokenType::Type, uint32_t{ModDefaultLibrary}});
    CHECK(tokenAt(tokens, code.range("fn")) == std::pair{TokenType::Function, uint32_t{ModReadonly | ModDefaultLibrary}});
    CHECK(tokenAt(tokens, code.range("t")) == std::pair{TokenType::Variable, uint32_t{ModReadonly | ModDefaultLibrary}});
    CHECK(tokenAt(tokens, code.range("comment")).first == TokenType::Comment);
    CHECK(tokenAt(tokens, code.range("str")).first == TokenType::String);
    CHECK(tokenAt(tokens, code.range("op")).first == TokenType::Operator);
    // In order, without overlaps.
    for (size_t i = 1; i < tokens.size(); ++i) CHECK(tokens[i - 1].range.end <= tokens[i].range.begin);
}

TEST_CASE("semantic tokens work on a broken script", "[semantic]") {
    Annotations code(R"($v«ball» = 1
Sphere { $attr«radius» -> ) }
$kw«Scene» { $use«ball» }
)");
    auto a = analyzeCode(code.code);
    REQUIRE(a->syntaxErrors);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("attr")).first == TokenType::Property);
    CHECK(tokenAt(tokens, code.range("kw")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("v")) == std::pair{TokenType::Variable, uint32_t{ModDeclaration | ModDefinition}});
    CHECK(tokenAt(tokens, code.range("use")) == std::pair{TokenType::Variable, uint32_t{0}});
}

TEST_CASE("semantic tokens of a range hold only that range", "[semantic]") {
    Annotations code("a = 1\n«b = 2»\nc = 3\n");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a, code.range());
    REQUIRE(tokens.size() == 3);
    CHECK(textOf(*a, tokens[0].range) == "b");
    CHECK(textOf(*a, tokens[2].range) == "2");
}

TEST_CASE("semantic tokens: material and matrix in a modifier list are keywords, a list by name a "
          "variable",
          "[semantic]") {
    Annotations code(R"(m = Material { $attr«material» -> 1 }
$def«spin» = <rotate vec3(0, 30, 0), $word«material» m>
s = Sphere { center -> vec3(0, 0, 0) radius -> 1 } <$use«spin», $word2«matrix» [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0]>
)");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("attr")).first == TokenType::Property);
    CHECK(tokenAt(tokens, code.range("word")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("word2")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("def")) ==
          std::pair{TokenType::Variable, uint32_t{ModDeclaration | ModDefinition}});
    CHECK(tokenAt(tokens, code.range("use")) == std::pair{TokenType::Variable, uint32_t{0}});
}

TEST_CASE("semantic tokens: shadow, camera and reflected are keywords in a modifier list only",
          "[semantic]") {
    Annotations code(R"($def«camera» = Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }
s = Sphere { center -> vec3(0, 0, 0) radius -> 1 } <$w1«shadow» false, $w2«camera» false>
Settings { $attr«camera» -> $use«camera» }
Scene { s }
)");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("w1")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("w2")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("attr")).first == TokenType::Property);
    CHECK(tokenAt(tokens, code.range("def")).first == TokenType::Variable);
    CHECK(tokenAt(tokens, code.range("use")).first == TokenType::Variable);
}

TEST_CASE("semantic tokens: a component's name is a property, its vector a variable",
          "[semantic]") {
    Annotations code("v = vec3(1, 2, 3)\nx = $v«v».$c«z»\n");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("v")).first == TokenType::Variable);
    CHECK(tokenAt(tokens, code.range("c")).first == TokenType::Property);
}

TEST_CASE("semantic tokens of a Function: the keyword and its parameters", "[semantic]") {
    Annotations code(R"(r = 2
f = $kw«Function» ($pdef«x», y, z) { $param«x» * y - r + z }
Scene { Isosurface { function -> f } }
)");
    auto a = analyzeCode(code.code);
    auto tokens = semanticTokens(*a);
    CHECK(tokenAt(tokens, code.range("kw")).first == TokenType::Keyword);
    CHECK(tokenAt(tokens, code.range("pdef")) == std::pair{TokenType::Parameter, uint32_t{ModDeclaration | ModDefinition}});
    CHECK(tokenAt(tokens, code.range("param")) == std::pair{TokenType::Parameter, uint32_t{0}});
}
