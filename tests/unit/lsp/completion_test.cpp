// Context-aware completion, on valid and broken scripts.
#include "annotations.hpp"
#include "completion.hpp"

#include <algorithm>

using namespace crt::lsp;
using namespace crt::lsp::test;

namespace {

std::vector<std::string> labels(const CompletionList& list) {
    std::vector<std::string> out;
    for (const CompletionItem& item : list.items) out.push_back(item.label);
    return out;
}

bool has(const CompletionList& list, const std::string& label) {
    auto l = labels(list);
    return std::find(l.begin(), l.end(), label) != l.end();
}

const CompletionItem& item(const CompletionList& list, const std::string& label) {
    for (const CompletionItem& i : list.items) {
        if (i.label == label) return i;
    }
    FAIL("no completion " << label);
    return list.items.front();
}

CompletionList completeAt(const std::string& marked) {
    Annotations code(marked);
    auto a = analyzeCode(code.code);
    return complete(*a, code.point(), testOptions());
}

} // namespace

TEST_CASE("inside an object: its attributes not yet given", "[completion]") {
    auto list = completeAt("Scene { Sphere { radius -> 1 @ } }");
    CHECK(has(list, "center"));
    CHECK(has(list, "material"));
    CHECK_FALSE(has(list, "radius"));
    CHECK_FALSE(has(list, "cornerA"));
    CHECK_FALSE(has(list, "Sphere"));
    const CompletionItem& center = item(list, "center");
    CHECK(center.insertText == "center -> ");
    CHECK(center.detail == "vec3 (required)");
    CHECK(center.sortText < item(list, "material").sortText);
}

TEST_CASE("attributes complete while the object is unfinished", "[completion]") {
    Annotations code("x = 1\nScene {\n    Camera { posi@\n}\n");
    auto a = analyzeCode(code.code);
    REQUIRE(a->syntaxErrors);
    auto list = complete(*a, code.point(), testOptions());
    CHECK(has(list, "position"));
    CHECK(has(list, "fov"));
    CHECK(textOf(*a, list.replace) == "posi");
}

TEST_CASE("Settings attributes", "[completion]") {
    auto list = completeAt("Settings { width -> 10 @\n");
    CHECK(has(list, "height"));
    CHECK(has(list, "lights"));
    CHECK_FALSE(has(list, "width"));
}

TEST_CASE("after '->': values of the attribute's type", "[completion]") {
    SECTION("a vec3") {
        auto list = completeAt("p = vec3(1, 2, 3)\nn = 2\ncol = rgb(1, 0, 0)\nScene { Sphere { center -> @ } }");
        CHECK(has(list, "vec3"));
        CHECK(item(list, "vec3").snippet);
        CHECK(has(list, "p"));
        CHECK_FALSE(has(list, "col"));
        CHECK_FALSE(has(list, "n"));
        CHECK_FALSE(has(list, "Sphere"));
    }
    SECTION("a material: material variables, from included files too, and the constructor") {
        auto list = completeAt("include \"materials.crt\"\nshiny = Material { reflectivity -> 0.9 }\nScene { Sphere { material -> @ } }");
        CHECK(has(list, "Material"));
        CHECK(has(list, "shiny"));
        CHECK(item(list, "shiny").sortText < item(list, "Material").sortText + "z");
        CHECK_FALSE(has(list, "Sphere"));
        CHECK_FALSE(has(list, "vec3"));
        CHECK(has(list, "MaterialMap")); // the materials made of others stand there too
        CHECK(has(list, "Layered"));
    }
    SECTION("a material map's entries and a Layered's layers, and the map's pattern") {
        auto entries = completeAt("m = MaterialMap { pattern -> Bozo { } materials -> @ }");
        CHECK(has(entries, "[[0, …], [1, …]]"));
        CHECK(item(entries, "[[0, …], [1, …]]").snippet);
        CHECK(has(completeAt("m = Layered { materials -> @ }"), "[…, …]"));
        auto pattern = completeAt("m = MaterialMap { pattern -> @ }");
        CHECK(has(pattern, "Granite"));
        CHECK_FALSE(has(pattern, "NoiseBump"));
        CHECK_FALSE(has(pattern, "Material"));
    }
    SECTION("a colour") {
        auto list = completeAt("Settings { background -> @");
        CHECK(has(list, "rgb"));
        CHECK(has(list, "Background"));
    }
    SECTION("a choice") {
        auto list = completeAt("Settings { antialias -> @ }");
        CHECK(has(list, "\"adaptive\""));
    }
    SECTION("a pattern's colour map, waveform and turbulence") {
        auto map = completeAt("m = Material { texture -> Onion { colors -> @ } }");
        CHECK(has(map, "[[0, …], [1, …]]"));
        CHECK(item(map, "[[0, …], [1, …]]").snippet);
        CHECK(has(completeAt("t = Spiral { waveform -> @ }"), "\"scallop\""));
        CHECK(has(completeAt("t = Leopard { turbulence -> @ }"), "vec3"));
    }
    SECTION("a bool") {
        auto list = completeAt("Cylinder { open -> @ }");
        CHECK(has(list, "true"));
        CHECK(has(list, "false"));
    }
}

TEST_CASE("at statement start: object types, keywords, names in scope", "[completion]") {
    auto list = completeAt("radius = 2\ngrow = Macro (k) { k }\n@");
    CHECK(has(list, "Sphere"));
    CHECK(has(list, "Scene"));
    CHECK(has(list, "while"));
    CHECK(has(list, "radius"));
    CHECK(has(list, "grow"));
    CHECK(has(list, "sin"));
    CHECK_FALSE(has(list, "k")); // a parameter of grow, not in scope here
    CHECK(item(list, "grow").insertText == "grow(${1:k})");
    CHECK(item(list, "Sphere").insertText == "Sphere { center -> ${1:vec3(0, 0, 0)} radius -> ${2:1.0} }$0");
}

TEST_CASE("inside a macro its locals are in scope", "[completion]") {
    auto list = completeAt("outer = 1\nm = Macro (size) {\n    inner = size\n    @\n}");
    CHECK(has(list, "size"));
    CHECK(has(list, "inner"));
    CHECK(has(list, "outer"));
}

TEST_CASE("include file names", "[completion]") {
    auto list = completeAt("include @");
    CHECK(has(list, "colors.crt"));
    CHECK(item(list, "colors.crt").insertText == "\"colors.crt\"");
    auto inString = completeAt("include \"ma@\"");
    CHECK(has(inString, "materials.crt"));
    CHECK(item(inString, "materials.crt").insertText == "materials.crt");
    auto unterminated = completeAt("x = 1\ninclude \"sha@");
    CHECK(has(unterminated, "shapes.crt"));
    CHECK(item(unterminated, "shapes.crt").insertText == "shapes.crt");
}

TEST_CASE("modifiers after '<'", "[completion]") {
    auto list = completeAt("s = Sphere { center -> vec3(0, 0, 0) radius -> 1 } <@");
    CHECK(has(list, "translate"));
    CHECK(has(list, "rotate"));
    CHECK(has(list, "scale"));
    CHECK(has(list, "material"));
    CHECK(has(list, "matrix"));
    for (const char* hides : {"shadow", "camera", "reflected"}) CHECK(has(list, hides));
    CHECK(list.items.size() == 8);
}

TEST_CASE("nothing inside comments", "[completion]") {
    auto list = completeAt("-- Sph@");
    CHECK(list.items.empty());
}

TEST_CASE("snippets read as plain text for clients without snippets", "[completion]") {
    CHECK(snippetToPlain("Sphere { center -> ${1:vec3(0, 0, 0)} radius -> ${2:1.0} }$0") ==
          "Sphere { center -> vec3(0, 0, 0) radius -> 1.0 }");
    CHECK(snippetToPlain("f(${1})") == "f()");
}

TEST_CASE("a name bound nowhere, such as the word being typed, is not offered", "[completion]") {
    auto list = completeAt("size = 1\nScene { Sphere { center -> vec3(0, 0, 0) radius -> si@ } }\n");
    CHECK(has(list, "size"));
    CHECK(!has(list, "si"));
}

TEST_CASE("components after '.': a vec3's, a colour's, or both when the type is unknown",
          "[completion]") {
    auto vector = completeAt("v = vec3(1, 2, 3)\nx = v.@");
    CHECK(labels(vector) == std::vector<std::string>{"x", "y", "z"});
    auto colour = completeAt("c = rgb(1, 0, 0)\nx = c.@");
    CHECK(labels(colour) == std::vector<std::string>{"r", "g", "b", "a"});
    auto unknown = completeAt("m = Macro (p) { p.@ }");
    CHECK(unknown.items.size() == 7);
}
