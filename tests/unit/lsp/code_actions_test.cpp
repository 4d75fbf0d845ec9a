// Quick fixes from the front end's fix-its.
#include "annotations.hpp"
#include "code_actions.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;

TEST_CASE("did-you-mean and missing attributes become quick fixes", "[code-actions]") {
    crt::lang::EvalOptions options;
    std::string text = "Scene { Sphere { center -> vec3(0, 0, 0) radus -> 1 } }\n";
    auto c = crt::lang::compile("a.crt", text, options);
    auto diagnostics = documentDiagnostics(c);
    auto actions = codeActions(diagnostics, text, 0, static_cast<uint32_t>(text.size()));
    REQUIRE(actions.size() == 1);
    CHECK(actions[0].title == "Change 'radus' to 'radius'");
    REQUIRE(actions[0].edits.size() == 1);
    CHECK(actions[0].edits[0].newText == "radius");
    CHECK(text.substr(actions[0].edits[0].range.begin, 5) == "radus");

    std::string missing = "Scene { Sphere { center -> vec3(0, 0, 0) } }\n";
    auto c2 = crt::lang::compile("b.crt", missing, options);
    auto actions2 = codeActions(documentDiagnostics(c2), missing, 8, 8);
    REQUIRE(actions2.size() == 1);
    CHECK(actions2[0].title == "Add the missing attribute 'radius -> 1.0'");
    std::string fixed = missing;
    fixed.insert(actions2[0].edits[0].range.begin, actions2[0].edits[0].newText);
    auto c3 = crt::lang::compile("c.crt", fixed, options);
    CHECK_FALSE(c3.diagnostics.hasErrors());
}

TEST_CASE("no quick fixes outside the range", "[code-actions]") {
    crt::lang::EvalOptions options;
    std::string text = "x = 1\nScene { Sphere { center -> vec3(0, 0, 0) radus -> 1 } }\n";
    auto c = crt::lang::compile("a.crt", text, options);
    CHECK(codeActions(documentDiagnostics(c), text, 0, 3).empty());
}
