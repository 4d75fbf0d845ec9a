// Diagnostics placed in the document: problems of included files land on the include.
#include "annotations.hpp"
#include "diagnostics.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;
using Catch::Matchers::Contains;

TEST_CASE("an error inside an included file is shown at the include", "[diagnostics]") {
    TempDir dir;
    dir.write("bad.crt", "x = 1\ny = (2 +\n");
    Annotations code("a = 1\n«include \"bad.crt\"»\nScene { }\n");
    std::string path = dir.write("main.crt", code.code);
    crt::lang::EvalOptions options;
    auto c = crt::lang::compileFile(path, options);
    auto diagnostics = documentDiagnostics(c);
    REQUIRE(!diagnostics.empty());
    const DocumentDiagnostic& first = diagnostics[0];
    CHECK(first.range == code.range());
    CHECK_THAT(first.message, Contains("bad.crt:2:9:")); // just after the last token, not on the empty line
    REQUIRE(first.related.size() == 1);
    CHECK(first.related[0].file->path().ends_with("bad.crt"));
    for (const DocumentDiagnostic& d : diagnostics) CHECK(d.range.file == 0);
}

TEST_CASE("warnings carry their code and notes", "[diagnostics]") {
    crt::lang::EvalOptions options;
    auto c = crt::lang::compile(
        "w.crt",
        "unused = 1\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 1 radius -> 2 } }\n"
        "Settings { ambient -> rgb(0.2, 0.2, 0.2) }\n",
        options);
    auto diagnostics = documentDiagnostics(c);
    REQUIRE(diagnostics.size() == 2);
    CHECK(diagnostics[0].code == "duplicate-attribute");
    REQUIRE(diagnostics[0].related.size() == 1);
    CHECK(diagnostics[0].related[0].message == "first given here");
    CHECK(diagnostics[1].code == "unused-variable");
    CHECK(diagnostics[1].severity == crt::lang::Severity::Warning);
}

TEST_CASE("a limit's diagnostic names the server setting that raises it, not crtc's option", "[diagnostics]") {
    crt::lang::EvalOptions options;
    options.limits.maxSteps = 1000;
    auto c = crt::lang::compile("loop.crt", "while (true) { }\n", options);
    auto diagnostics = documentDiagnostics(c);
    REQUIRE(!diagnostics.empty());
    CHECK_THAT(diagnostics[0].message, Contains("exceeded 1000 steps"));
    CHECK_THAT(diagnostics[0].message, Contains("with the language server's maxSteps setting (crt.maxSteps in VS Code)"));
    CHECK_THAT(diagnostics[0].message, !Contains("--max-steps"));
}
