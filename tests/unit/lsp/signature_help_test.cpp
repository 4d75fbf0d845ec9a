// Signature help for built-ins and macros.
#include "annotations.hpp"
#include "signature_help.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;

TEST_CASE("signature help of a built-in tracks the argument", "[signature]") {
    Annotations code("c = rgb(@1, @0.5, vec3(1, 2, 3)@, @");
    auto a = analyzeCode(code.code);
    auto first = signatureHelp(*a, code.points()[0]);
    REQUIRE(first);
    CHECK(first->label == "rgb(r, g, b)");
    CHECK(first->activeParameter == 0);
    REQUIRE(first->parameters.size() == 3);
    CHECK(first->label.substr(first->parameters[1].first, first->parameters[1].second - first->parameters[1].first) == "g");
    CHECK(signatureHelp(*a, code.points()[1])->activeParameter == 1);
    auto inner = signatureHelp(*a, code.points()[2]);
    REQUIRE(inner);
    CHECK(inner->label == "rgb(r, g, b)"); // just after the inner call's ')': back in rgb
    CHECK(inner->activeParameter == 2);
    CHECK(signatureHelp(*a, code.points()[3])->activeParameter == 2); // clamped: one too many
}

TEST_CASE("signature help of a macro", "[signature]") {
    Annotations code("ring = Macro (count, radius) { count }\nScene { ring(3, @) }");
    auto a = analyzeCode(code.code);
    auto help = signatureHelp(*a, code.point());
    REQUIRE(help);
    CHECK(help->label == "ring(count, radius)");
    CHECK(help->activeParameter == 1);
}

TEST_CASE("no signature help outside calls", "[signature]") {
    Annotations code("x = (1 + @2)\ny = [1, @]");
    auto a = analyzeCode(code.code);
    CHECK_FALSE(signatureHelp(*a, code.points()[0]));
    CHECK_FALSE(signatureHelp(*a, code.points()[1]));
}
