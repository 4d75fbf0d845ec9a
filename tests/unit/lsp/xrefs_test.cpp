// Definition, references, highlights and rename, within a file and across includes.
#include "annotations.hpp"
#include "xrefs.hpp"

using namespace crt::lsp;
using namespace crt::lsp::test;

namespace {

std::vector<crt::lang::SourceRange> inDocument(const std::vector<Location>& locations, const Analysis& a) {
    std::vector<crt::lang::SourceRange> out;
    for (const Location& l : locations) {
        if (l.file == &a.file()) out.push_back(l.range);
    }
    return out;
}

const char* kScopes = R"($g«count» = 2
grow = Macro ($p«size», k) {
    $l«inner» = $p«si@ze» * k + $g«count»
    Sphere { center -> vec3(0, 0, 0) radius -> $l«inn@er» }
}
$g«count» = $g«cou@nt» + 1
Scene { grow(1, $g«count») }
)";

} // namespace

TEST_CASE("a parameter: definition and references stay in its macro", "[xrefs]") {
    Annotations code(kScopes);
    auto a = analyzeCode(code.code);
    auto def = definition(*a, code.points()[0]);
    REQUIRE(def.size() == 1);
    CHECK(def[0].file == &a->file());
    CHECK(def[0].range == code.ranges("p")[0]);
    CHECK(inDocument(references(*a, code.points()[0], true), *a) == code.ranges("p"));
    CHECK(inDocument(references(*a, code.points()[0], false), *a).size() == 1);
}

TEST_CASE("a macro local", "[xrefs]") {
    Annotations code(kScopes);
    auto a = analyzeCode(code.code);
    auto def = definition(*a, code.points()[1]);
    REQUIRE(def.size() == 1);
    CHECK(def[0].range == code.ranges("l")[0]);
    CHECK(inDocument(references(*a, code.points()[1], true), *a) == code.ranges("l"));
}

TEST_CASE("a global read inside and outside a macro", "[xrefs]") {
    Annotations code(kScopes);
    auto a = analyzeCode(code.code);
    auto def = definition(*a, code.points()[2]);
    REQUIRE(def.size() == 1);
    CHECK(def[0].range == code.ranges("g")[0]);
    CHECK(inDocument(references(*a, code.points()[2], true), *a) == code.ranges("g"));
    auto highlights = documentHighlights(*a, code.points()[2]);
    REQUIRE(highlights.size() == 5);
    std::vector<bool> writes;
    for (const Highlight& h : highlights) writes.push_back(h.write);
    CHECK(writes == std::vector<bool>{true, false, true, false, false});
}

TEST_CASE("rename checks the new name", "[xrefs]") {
    Annotations code(kScopes);
    auto a = analyzeCode(code.code);
    auto options = testOptions();
    auto check = prepareRename(*a, code.points()[2], options);
    REQUIRE(check.range);
    CHECK(check.placeholder == "count");
    RenameResult ok = rename(*a, code.points()[2], "total", options);
    CHECK(ok.error.empty());
    CHECK(inDocument(ok.edits, *a) == code.ranges("g"));
    CHECK_FALSE(rename(*a, code.points()[2], "inner", options).error.empty()); // would be captured
    CHECK_FALSE(rename(*a, code.points()[2], "Total", options).error.empty());
    CHECK_FALSE(rename(*a, code.points()[2], "while", options).error.empty());
    CHECK_FALSE(rename(*a, code.points()[2], "a b", options).error.empty());
}

TEST_CASE("a compound assignment is one occurrence, a write, and renames once", "[xrefs]") {
    Annotations code("$g«total» = 0\nfor i in range(3) { $g«tot@al» += i }\nprint($g«total»)\n");
    auto a = analyzeCode(code.code);
    CHECK(inDocument(references(*a, code.points()[0], true), *a) == code.ranges("g"));
    auto highlights = documentHighlights(*a, code.points()[0]);
    std::vector<bool> writes;
    for (const Highlight& h : highlights) writes.push_back(h.write);
    CHECK(writes == std::vector<bool>{true, true, false});
    RenameResult renamed = rename(*a, code.points()[0], "sum", testOptions());
    CHECK(renamed.error.empty());
    CHECK(inDocument(renamed.edits, *a) == code.ranges("g"));
}

TEST_CASE("built-ins and non-names cannot be renamed", "[xrefs]") {
    Annotations code("x = s@in(1) + 2@");
    auto a = analyzeCode(code.code);
    CHECK_FALSE(prepareRename(*a, code.points()[0], testOptions()).range);
    CHECK_FALSE(prepareRename(*a, code.points()[1], testOptions()).range);
    CHECK(definition(*a, code.points()[0]).empty());
}

TEST_CASE("definition and references across included files", "[xrefs]") {
    TempDir dir;
    dir.write("lib.crt", "shared = 3\nhelper = Macro (a) { a * shared }\n");
    Annotations code("include \"li@b.crt\"\nx = hel@per(shar@ed)\nScene { x }\n");
    auto a = analyzeIn(dir, code.code);
    REQUIRE(a->includes.size() == 1);
    auto def = definition(*a, code.points()[1]);
    REQUIRE(def.size() == 1);
    REQUIRE(def[0].file != &a->file());
    CHECK(def[0].file->path().ends_with("lib.crt"));
    CHECK(def[0].range.begin == 11); // "helper" on the second line of lib.crt
    auto refs = references(*a, code.points()[2], true);
    CHECK(refs.size() == 3); // two in lib.crt, one here
    auto file = definition(*a, code.points()[0]);
    REQUIRE(file.size() == 1);
    CHECK(file[0].file->path().ends_with("lib.crt"));
}

TEST_CASE("names resolve in a broken script", "[xrefs]") {
    Annotations code("$d«ball» = 1\nScene { Sphere { radius -> ) } }\nx = ba@ll\n");
    auto a = analyzeCode(code.code);
    REQUIRE(a->syntaxErrors);
    auto def = definition(*a, code.point());
    REQUIRE(def.size() == 1);
    CHECK(def[0].range == code.range("d"));
}

TEST_CASE("a Function's parameters: definition and references stay in its body", "[xrefs]") {
    // The global x outside is another name than the parameter x inside.
    Annotations code(R"($g«x» = 2
f = Function ($p«x», y, z) { $p«x» * $p«@x» + y - z }
print(f($g«@x», 0, 0))
)");
    auto a = analyzeCode(code.code);
    auto def = definition(*a, code.points()[0]);
    REQUIRE(def.size() == 1);
    CHECK(def[0].range == code.ranges("p")[0]);
    CHECK(inDocument(references(*a, code.points()[0], true), *a) == code.ranges("p"));
    CHECK(inDocument(references(*a, code.points()[1], true), *a) == code.ranges("g"));
}
