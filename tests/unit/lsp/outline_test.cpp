// Document symbols and folding ranges.
#include "annotations.hpp"
#include "document_symbols.hpp"
#include "folding.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;

TEST_CASE("document symbols are hierarchical", "[outline]") {
    Annotations code(R"(include "colors.crt"
Settings { width -> 320 height -> 200 }
$ball«ball» = Sphere { center -> vec3(0, 0, 0) radius -> 1 }
grow = Macro (k) {
    part = Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(k, k, k) }
    part
}
Scene {
    ball
    Plane { normal -> vec3(0, 1, 0) position -> vec3(0, 0, 0) }
}
)");
    auto a = analyzeCode(code.code);
    auto symbols = documentSymbols(*a);
    REQUIRE(symbols.size() == 5);
    CHECK(symbols[0].kind == OutlineKind::File);
    CHECK(symbols[1].name == "Settings");
    REQUIRE(symbols[1].children.size() == 2);
    CHECK(symbols[1].children[1].name == "height");
    CHECK(symbols[1].children[1].detail == "200");
    CHECK(symbols[2].name == "ball");
    CHECK(symbols[2].kind == OutlineKind::Object);
    CHECK(symbols[2].detail == "Sphere");
    CHECK(symbols[2].selection == code.range("ball"));
    CHECK(symbols[2].children.size() == 2);
    CHECK(symbols[3].name == "grow");
    CHECK(symbols[3].kind == OutlineKind::Function);
    REQUIRE(symbols[3].children.size() == 1);
    CHECK(symbols[3].children[0].name == "part");
    CHECK(symbols[3].children[0].children.size() == 2);
    CHECK(symbols[4].name == "Scene");
    REQUIRE(symbols[4].children.size() == 1);
    CHECK(symbols[4].children[0].name == "Plane");
}

TEST_CASE("document symbols of a broken script keep what parsed", "[outline]") {
    auto a = analyzeCode("a = 1\nb = )\nc = Sphere { radius -> 1 }\n");
    auto symbols = documentSymbols(*a);
    REQUIRE(symbols.size() == 2);
    CHECK(symbols[0].name == "a");
    CHECK(symbols[1].name == "c");
}

TEST_CASE("folding ranges for blocks, lists and comment runs", "[outline]") {
    auto a = analyzeCode(R"(-- A scene.
-- Two lines of header.
Scene {
    Sphere {
        radius -> 1
        center -> vec3(0, 0, 0)
    }
    x = [
        1,
        2
    ]
}
y = 1 -- trailing
)");
    auto ranges = foldingRanges(*a);
    REQUIRE(ranges.size() == 4);
    CHECK((ranges[0].startLine == 0 && ranges[0].endLine == 1 && ranges[0].comment));
    CHECK((ranges[1].startLine == 2 && ranges[1].endLine == 10 && !ranges[1].comment));
    CHECK((ranges[2].startLine == 3 && ranges[2].endLine == 5));
    CHECK((ranges[3].startLine == 7 && ranges[3].endLine == 9));
}
