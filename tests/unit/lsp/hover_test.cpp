// Hover on names, object types, attributes and built-ins.
#include "annotations.hpp"
#include "hover.hpp"

#include <sstream>

using namespace crt::lsp;
using namespace crt::lsp::test;
using Catch::Matchers::Contains;

TEST_CASE("hover on an object type lists its attributes", "[hover]") {
    Annotations code("Scene { Sph@ere { center -> vec3(0, 0, 0) radius -> 1 } }");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.point(), nullptr);
    REQUIRE(h);
    CHECK(textOf(*a, h->range) == "Sphere");
    CHECK_THAT(h->markdown, Contains("`radius`") && Contains("`material`"));
}

TEST_CASE("hover on an attribute gives its type and default", "[hover]") {
    Annotations code("m = Material { refl@ectivity -> 0.5 }\nc = Camera { position -> vec3(0, 0, -1) pointing -> vec3(0, 0, 0) f@ov -> 50 }");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.points()[0], nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("Material.reflectivity: float") && Contains("Default: `0`"));
    auto fov = hover(*a, code.points()[1], nullptr);
    REQUIRE(fov);
    CHECK_THAT(fov->markdown, Contains("Camera.fov") && Contains("60"));
}

TEST_CASE("hover on a built-in gives its signature", "[hover]") {
    Annotations code("x = cl@amp(2, 0, 1)\ny = t@");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.points()[0], nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("clamp(x, lo, hi)") && Contains("limited"));
    auto t = hover(*a, code.points()[1], nullptr);
    REQUIRE(t);
    CHECK_THAT(t->markdown, Contains("animation time"));
}

TEST_CASE("hover on a variable shows its type and evaluated value", "[hover]") {
    Annotations code("ce@nter = vec3(0.5, 0.5, 0)\nba@ll = Sphere { center -> center radius -> 0.68 }\nScene { ball }\ngrow = Macro (s@ize) { size }");
    auto a = analyzeCode(code.code);
    GlobalValues values{{"center", "vec3(0.5, 0.5, 0.0)"}};
    auto h = hover(*a, code.points()[0], &values);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("(variable) center: vec3") && Contains("vec3(0.5, 0.5, 0.0)"));
    auto ball = hover(*a, code.points()[1], nullptr);
    REQUIRE(ball);
    CHECK_THAT(ball->markdown, Contains("ball: Sphere") && Contains("radius -> 0.68"));
    auto size = hover(*a, code.points()[2], nullptr);
    REQUIRE(size);
    CHECK_THAT(size->markdown, Contains("(parameter) size"));
}

TEST_CASE("hover on an undefined name says so, with the nearest defined name", "[hover]") {
    Annotations code("radius = 2\nball = Sphere { center -> vec3(0, 0, 0) radius -> rad@ios }\nx = "
                     "zz@zq\nScene { ball }");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.points()[0], nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown,
               Contains("Undefined") && Contains("`radios`") && Contains("Did you mean `radius`?"));
    auto far = hover(*a, code.points()[1], nullptr);
    REQUIRE(far);
    CHECK_THAT(far->markdown, Contains("Undefined") && !Contains("Did you mean"));
    // A defined name is not.
    Annotations defined("radius = 2\nx = rad@ius");
    auto b = analyzeCode(defined.code);
    auto d = hover(*b, defined.point(), nullptr);
    REQUIRE(d);
    CHECK_THAT(d->markdown, !Contains("Undefined"));
}

TEST_CASE("hover on a list of modifiers held in a variable says so", "[hover]") {
    Annotations code("sp@in = <rotate vec3(0, 30, 0), translate vec3(1, 0, 0)>");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.point(), nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("(variable) spin: modifiers"));
}

TEST_CASE("hover values come from a real evaluation", "[hover]") {
    crt::lang::EvalOptions options;
    options.keepGlobalValues = true;
    std::ostringstream printed;
    options.printOut = &printed;
    auto c = crt::lang::compile("v.crt", "k = vec3(1, 2, 3) * 2\ns = \"hi\"\nprint(k, s)\nb = Sphere { center -> k radius -> 1 }\nScene { b }\n", options);
    GlobalValues values = c.globalValues;
    REQUIRE(values.size() == 3);
    CHECK(values[2] == std::pair<std::string, std::string>{"b", "<Sphere 4:5>"});
    CHECK(values[0] == std::pair<std::string, std::string>{"k", "vec3(2.0, 4.0, 6.0)"});
    CHECK(values[1].second == "\"hi\"");
}

TEST_CASE("hover works on a broken script", "[hover]") {
    Annotations code("size = 2\nScene { Sphere { radius -> si@ze + } \n");
    auto a = analyzeCode(code.code);
    REQUIRE(a->syntaxErrors);
    auto h = hover(*a, code.point(), nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("size: int"));
}

TEST_CASE("hover on an attribute of an object the parser dropped", "[hover]") {
    Annotations code("Scene { Box { cor@nerA -> vec3(0, 0, 0) cornerB -> ) } }\nSettings { wid@th -> ( }\nx = Cone { ba@se -> vec3(0, 0, 0) top -> \n");
    auto a = analyzeCode(code.code);
    REQUIRE(a->syntaxErrors);
    auto h = hover(*a, code.points()[0], nullptr);
    REQUIRE(h);
    CHECK_THAT(h->markdown, Contains("Box.cornerA: vec3"));
    auto w = hover(*a, code.points()[1], nullptr);
    REQUIRE(w);
    CHECK_THAT(w->markdown, Contains("Settings.width: int"));
    auto b = hover(*a, code.points()[2], nullptr);
    REQUIRE(b);
    CHECK_THAT(b->markdown, Contains("Cone.base: vec3"));
}

TEST_CASE("hover on nothing is empty", "[hover]") {
    Annotations code("x = 1   @\n-- comm@ent");
    auto a = analyzeCode(code.code);
    CHECK_FALSE(hover(*a, code.points()[0], nullptr));
    CHECK_FALSE(hover(*a, code.points()[1], nullptr));
}

TEST_CASE("hover on a pattern's attributes gives their types and defaults", "[hover]") {
    Annotations code("t = Spiral { arms -> 3 col@ors -> [[0, rgb(0, 0, 0)], [1, rgb(1, 1, 1)]] wave@form -> \"sine\" turb@ulence -> 0.2 }");
    auto a = analyzeCode(code.code);
    auto colors = hover(*a, code.points()[0], nullptr);
    REQUIRE(colors);
    CHECK_THAT(colors->markdown, Contains("Spiral.colors: colour map") && Contains("rgb(0, 0, 0)"));
    auto waveform = hover(*a, code.points()[1], nullptr);
    REQUIRE(waveform);
    CHECK_THAT(waveform->markdown, Contains("Default: `\"triangle\"`"));
    auto turbulence = hover(*a, code.points()[2], nullptr);
    REQUIRE(turbulence);
    CHECK_THAT(turbulence->markdown, Contains("float or vec3"));
}

TEST_CASE("hover on a material map's and a Layered's attributes and types", "[hover]") {
    Annotations code("m = MaterialMap { pat@tern -> Gradient { } mate@rials -> [[0, Material { }], "
                     "[1, Material { fil@ter -> 0.5 }]] }\n"
                     "l = Lay@ered { materials -> [m] }");
    auto a = analyzeCode(code.code);
    auto pattern = hover(*a, code.points()[0], nullptr);
    REQUIRE(pattern);
    CHECK_THAT(pattern->markdown, Contains("MaterialMap.pattern: texture"));
    auto materials = hover(*a, code.points()[1], nullptr);
    REQUIRE(materials);
    CHECK_THAT(materials->markdown, Contains("MaterialMap.materials: material map"));
    auto filter = hover(*a, code.points()[2], nullptr);
    REQUIRE(filter);
    CHECK_THAT(filter->markdown, Contains("Material.filter: float") && Contains("Default: `0`"));
    auto layered = hover(*a, code.points()[3], nullptr);
    REQUIRE(layered);
    CHECK_THAT(layered->markdown, Contains("Layered"));
}

TEST_CASE("hover on a component says what it reads; a component expression is a float", "[hover]") {
    Annotations code("c = rgb(1, 0, 0)\nx = c.@a\ny = c.r\nz = @y");
    auto a = analyzeCode(code.code);
    auto h = hover(*a, code.points()[0], nullptr);
    REQUIRE(h);
    CHECK(textOf(*a, h->range) == "a");
    CHECK_THAT(h->markdown, Contains("alpha of a colour"));
    auto y = hover(*a, code.points()[1], nullptr);
    REQUIRE(y);
    CHECK_THAT(y->markdown, Contains("y: float"));
}
