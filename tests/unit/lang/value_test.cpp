// Value semantics (spec §3) through tiny scripts, plus formatFloat, quoted and closestMatch.
#include <catch2/catch.hpp>

#include "diagnostic.hpp"
#include "interpreter.hpp"
#include "value_format.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace crt::lang;

namespace {

struct Run {
    std::string out;                 ///< what print() wrote
    std::vector<std::string> errors; ///< error messages in order
    bool hasScene = false;
};

Run run(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("v.crt", text, options);
    Run r;
    r.out = out.str();
    for (const Diagnostic& d : c.diagnostics.items()) {
        if (d.severity == Severity::Error) r.errors.push_back(d.message);
    }
    r.hasScene = c.scene.has_value();
    return r;
}

/// The output of `print(expr)` without its newline; the script must have no error.
std::string show(const std::string& expr) {
    Run r = run("print(" + expr + ")\n");
    INFO("expression: " << expr);
    INFO("errors: " << (r.errors.empty() ? "" : r.errors[0]));
    REQUIRE(r.errors.empty());
    REQUIRE(!r.out.empty());
    REQUIRE(r.out.back() == '\n');
    return r.out.substr(0, r.out.size() - 1);
}

/// The single error message of evaluating `script`.
std::string errorOf(const std::string& script) {
    Run r = run(script);
    INFO("script: " << script);
    REQUIRE(r.errors.size() == 1);
    CHECK(!r.hasScene);
    return r.errors[0];
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("values: ints stay ints, mixing with a float gives a float") {
    CHECK(show("1 + 2") == "3");
    CHECK(show("2 * 3 - 1") == "5");
    CHECK(show("1 + 2.0") == "3.0");
    CHECK(show("2.0 + 1") == "3.0");
    CHECK(show("2 * 1.5") == "3.0");
    CHECK(show("7 / 2.0") == "3.5");
    CHECK(show("1.0 - 1") == "0.0");
    CHECK(show("-3") == "-3");
    CHECK(show("-3.5") == "-3.5");
    CHECK(show("+4") == "4");
    CHECK(show("3 == 3.0") == "true");
    CHECK(show("1 < 1.5") == "true");
    CHECK(show("2 >= 2.0") == "true");
}

TEST_CASE("values: print separates its arguments by spaces") {
    CHECK(show("1, 2.5, \"s\", true, false") == "1 2.5 s true false");
    CHECK(run("print()\n").out == "\n");
}

TEST_CASE("values: int overflow is an error") {
    CHECK(show("9223372036854775807") == "9223372036854775807");
    CHECK(contains(errorOf("x = 9223372036854775807 + 1\n"), "overflow"));
    CHECK(contains(errorOf("x = -9223372036854775807 - 2\n"), "overflow"));
    CHECK(contains(errorOf("x = 4294967296 * 4294967296\n"), "overflow"));
    CHECK(contains(errorOf("x = 9223372036854775808\n"), "64 bits"));
}

TEST_CASE("values: int '/' truncates toward zero") {
    CHECK(show("7 / 2, -7 / 2, 7 / -2, -7 / -2") == "3 -3 -3 3");
    CHECK(show("1 / 3, 0 / 5") == "0 0");
}

TEST_CASE("values: int '%' has the sign of the dividend") {
    CHECK(show("7 % 3, -7 % 3, 7 % -3, -7 % -3") == "1 -1 1 -1");
    CHECK(show("6 % 3, -6 % 3") == "0 0");
}

TEST_CASE("values: int division or modulo by zero is an error") {
    CHECK(errorOf("x = 1 / 0\n") == "integer division by zero");
    CHECK(errorOf("x = 1 % 0\n") == "integer modulo by zero");
}

TEST_CASE("values: float '%' is fmod") {
    CHECK(show("7.5 % 2") == "1.5");
    CHECK(show("-7.5 % 2") == "-1.5");
    CHECK(show("7.5 % -2") == "1.5");
    CHECK(show("5 % 2.5") == "0.0");
    CHECK(show("1 % 0.0") == "nan");
}

TEST_CASE("values: float division by zero gives infinities and NaN") {
    CHECK(show("1.0 / 0") == "inf");
    CHECK(show("-1 / 0.0") == "-inf");
    CHECK(show("0.0 / 0") == "nan");
    CHECK(show("1.0 / 0 - 1.0 / 0") == "nan");
}

TEST_CASE("values: a string plus a number or bool concatenates its str") {
    CHECK(show("\"a\" + 1") == "a1");
    CHECK(show("1 + \"a\"") == "1a");
    CHECK(show("\"x\" + 2.5") == "x2.5");
    CHECK(show("\"x\" + 2.0") == "x2.0");
    CHECK(show("\"b\" + true") == "btrue");
    CHECK(show("false + \"b\"") == "falseb");
    CHECK(show("\"s\" + \"t\"") == "st");
    CHECK(show("\"n=\" + 1 + 2") == "n=12");
    CHECK(show("1 + 2 + \"n\"") == "3n");
}

TEST_CASE("values: other string operations are errors") {
    CHECK(errorOf("x = \"a\" - 1\n") == "cannot apply '-' to string and int");
    CHECK(errorOf("x = \"a\" * 2\n") == "cannot apply '*' to string and int");
    CHECK(errorOf("x = \"a\" + vec3(1, 2, 3)\n") == "cannot apply '+' to string and vec3");
    CHECK(errorOf("x = \"a\" + [1]\n") == "cannot apply '+' to string and list");
}

TEST_CASE("values: vec3 arithmetic is component-wise") {
    CHECK(show("vec3(1, 2, 3)") == "vec3(1.0, 2.0, 3.0)");
    CHECK(show("vec3(1, 2, 3) + vec3(1, 1, 1)") == "vec3(2.0, 3.0, 4.0)");
    CHECK(show("vec3(1, 2, 3) - vec3(1, 1, 1)") == "vec3(0.0, 1.0, 2.0)");
    CHECK(show("vec3(1, 2, 3) * 2") == "vec3(2.0, 4.0, 6.0)");
    CHECK(show("2 * vec3(1, 2, 3)") == "vec3(2.0, 4.0, 6.0)");
    CHECK(show("0.5 * vec3(1, 2, 3)") == "vec3(0.5, 1.0, 1.5)");
    CHECK(show("vec3(1, 2, 3) / 2") == "vec3(0.5, 1.0, 1.5)");
    CHECK(show("vec3(1, 2, 3) * vec3(1, 2, 3)") == "vec3(1.0, 4.0, 9.0)");
    CHECK(show("-vec3(1, -2, 3)") == "vec3(-1.0, 2.0, -3.0)");
    CHECK(show("vec3(1, 2, 3) / 0") == "vec3(inf, inf, inf)");
}

TEST_CASE("values: a number divided by a vec3, or a vec3 plus a number, is an error") {
    CHECK(errorOf("x = 2 / vec3(1, 2, 3)\n") == "cannot apply '/' to int and vec3");
    CHECK(errorOf("x = vec3(1, 2, 3) + 1\n") == "cannot apply '+' to vec3 and int");
    CHECK(errorOf("x = 1.5 - vec3(1, 2, 3)\n") == "cannot apply '-' to float and vec3");
}

TEST_CASE("values: color arithmetic is component-wise too") {
    CHECK(show("rgb(0.25, 0.5, 1)") == "rgb(0.25, 0.5, 1.0)");
    CHECK(show("rgb(0.25, 0.5, 1) * 2") == "rgb(0.5, 1.0, 2.0)");
    CHECK(show("2 * rgb(0.25, 0.5, 1)") == "rgb(0.5, 1.0, 2.0)");
    CHECK(show("rgb(0.5, 0.5, 0.5) + rgb(0.25, 0, 1)") == "rgb(0.75, 0.5, 1.5)");
    CHECK(show("rgb(0.5, 0.5, 0.5) - rgb(0.25, 0, 1)") == "rgb(0.25, 0.5, -0.5)");
    CHECK(show("rgb(0.5, 1, 2) * rgb(2, 0.5, 0.25)") == "rgb(1.0, 0.5, 0.5)");
    CHECK(show("rgb(1, 2, 3) / 2") == "rgb(0.5, 1.0, 1.5)");
}

TEST_CASE("values: vec3 and color never mix") {
    CHECK(errorOf("x = vec3(1, 2, 3) + rgb(1, 2, 3)\n") == "cannot apply '+' to vec3 and colour");
    CHECK(errorOf("x = rgb(1, 2, 3) - vec3(1, 2, 3)\n") == "cannot apply '-' to colour and vec3");
    CHECK(errorOf("x = rgb(1, 2, 3) * vec3(1, 2, 3)\n") == "cannot apply '*' to colour and vec3");
    CHECK(errorOf("x = vec3(1, 2, 3) * rgb(1, 2, 3)\n") == "cannot apply '*' to vec3 and colour");
    CHECK(errorOf("x = vec3(1, 2, 3) / rgb(1, 2, 3)\n") == "cannot apply '/' to vec3 and colour");
}

TEST_CASE("values: the error of a wrongly typed operator is at the operator") {
    EvalOptions options;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("v.crt", "x = vec3(1, 2, 3) + rgb(1, 2, 3)\n", options);
    REQUIRE(c.diagnostics.errorCount() == 1);
    const Diagnostic& d = c.diagnostics.items()[0];
    CHECK(d.range.begin == 18);
    CHECK(d.range.end == 19);
}

TEST_CASE("values: '==' is structural on lists and vectors") {
    CHECK(show("[1, 2, [3, \"a\"]] == [1, 2, [3, \"a\"]]") == "true");
    CHECK(show("[1, 2] == [1, 2, 3]") == "false");
    CHECK(show("[1, 2] != [2, 1]") == "true");
    CHECK(show("[] == []") == "true");
    CHECK(show("[1] == [1.0]") == "true");
    CHECK(show("vec3(1, 2, 3) == vec3(1, 2, 3)") == "true");
    CHECK(show("vec3(1, 2, 3) == vec3(1, 2, 4)") == "false");
    CHECK(show("rgb(1, 2, 3) == rgb(1, 2, 3)") == "true");
    CHECK(show("rgba(1, 2, 3, 0.5) == rgb(1, 2, 3)") == "false");
    CHECK(show("\"ab\" == \"a\" + \"b\"") == "true");
    CHECK(show("true != false") == "true");
    CHECK(run("a = [vec3(1, 2, 3)]\nb = [vec3(1, 2, 3)]\nprint(a == b)\n").out == "true\n");
}

TEST_CASE("values: '==' is identity on objects and macros") {
    std::string defs = "m = Material { color -> rgb(1, 0, 0) }\n"
                       "n = Material { color -> rgb(1, 0, 0) }\n"
                       "k = m\n"
                       "f = Macro (x) { x }\n"
                       "g = Macro (x) { x }\n"
                       "h = f\n";
    Run r = run(defs + "print(m == m, m == n, k == m, m != n, f == f, f == g, h == f)\n");
    CHECK(r.errors.empty());
    CHECK(r.out == "true false true true true false true\n");
}

TEST_CASE("values: comparing values of different types is an error") {
    CHECK(contains(errorOf("x = 1 == \"1\"\n"), "int and string"));
    CHECK(contains(errorOf("x = true != 1\n"), "bool and int"));
    CHECK(contains(errorOf("x = vec3(1, 2, 3) == rgb(1, 2, 3)\n"), "vec3 and colour"));
    CHECK(contains(errorOf("x = [1] == vec3(1, 2, 3)\n"), "list and vec3"));
    CHECK(contains(errorOf("x = \"a\" < \"b\"\n"), "'<'"));
    CHECK(contains(errorOf("x = vec3(1, 2, 3) > vec3(0, 0, 0)\n"), "'>'"));
}

TEST_CASE("values: conditions must be bools") {
    CHECK(contains(errorOf("x = 1 && true\n"), "must be bools"));
    CHECK(contains(errorOf("x = !1\n"), "'!'"));
    CHECK(contains(errorOf("x = 1 ? 2 : 3\n"), "must be a bool"));
    CHECK(show("false && 1, true || 1") == "false true"); // short-circuit: 1 never checked
}

TEST_CASE("values: assignment copies, so changing a never changes b") {
    CHECK(run("a = vec3(1, 2, 3)\nb = a\na = a * 2\nprint(a, b)\n").out ==
          "vec3(2.0, 4.0, 6.0) vec3(1.0, 2.0, 3.0)\n");
    CHECK(run("a = [1, 2]\nb = a\na = [a, 3]\nprint(a, b)\n").out == "[[1, 2], 3] [1, 2]\n");
    CHECK(run("v = 1\nl = [v, v]\nv = 2\nprint(l, v)\n").out == "[1, 1] 2\n");
    CHECK(run("s = \"x\"\nt2 = s\ns = s + \"y\"\nprint(s, t2)\n").out == "xy x\n");
}

TEST_CASE("values: lists are values, so a macro cannot change its caller's list") {
    Run r = run("l = [1, 2]\n"
                "m = Macro (x) { x = [x, 0]\n x }\n"
                "r = m(l)\n"
                "print(l, r)\n");
    CHECK(r.errors.empty());
    CHECK(r.out == "[1, 2] [[1, 2], 0]\n");
}

TEST_CASE("values: a macro assigning an outer name makes a local") {
    Run r = run("x = 1\nm = Macro () { x = 2\n x }\nprint(m(), x)\n");
    CHECK(r.errors.empty());
    CHECK(r.out == "2 1\n");
}

TEST_CASE("values: list indexing") {
    CHECK(show("[10, 20, 30][1]") == "20");
    CHECK(errorOf("x = [10, 20][2]\n") == "index 2 is out of range for a list of length 2");
    CHECK(contains(errorOf("x = [10, 20][-1]\n"), "-1"));
    CHECK(contains(errorOf("x = [10, 20][1.0]\n"), "must be an int"));
}

TEST_CASE("values: str() formats every kind") {
    CHECK(show("str(2.0), str(0.5), str(1e20), str(7)") == "2.0 0.5 1e+20 7");
    CHECK(show("[1, \"a\", 2.5, true, [vec3(0, 0, 1)]]") == "[1, \"a\", 2.5, true, [vec3(0.0, 0.0, 1.0)]]");
    CHECK(show("str(\"s\") + str(true)") == "strue");
}

TEST_CASE("formatFloat: shortest round-trip text with '.0' added") {
    CHECK(formatFloat(0.5) == "0.5");
    CHECK(formatFloat(2.0) == "2.0");
    CHECK(formatFloat(0.0) == "0.0");
    CHECK(formatFloat(-0.0) == "-0.0");
    CHECK(formatFloat(-3.0) == "-3.0");
    CHECK(formatFloat(0.1) == "0.1");
    CHECK(formatFloat(0.1 + 0.2) == "0.30000000000000004");
    CHECK(formatFloat(1.0 / 3.0) == "0.3333333333333333");
    CHECK(formatFloat(123456789.0) == "123456789.0");
    CHECK(formatFloat(1e20) == "1e+20");
    CHECK(formatFloat(1.5e-7) == "1.5e-07");
    CHECK(formatFloat(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(formatFloat(-std::numeric_limits<double>::infinity()) == "-inf");
    CHECK(formatFloat(std::numeric_limits<double>::quiet_NaN()) == "nan");
    CHECK(formatFloat(-std::numeric_limits<double>::quiet_NaN()) == "nan");
}

TEST_CASE("formatFloat: the text reads back exactly") {
    for (double x : {0.1, 1.0 / 3.0, 2.0 / 3.0, 1e-300, 5e-324, 1.7976931348623157e308, 3.14159,
                     -2.5e10, 123.456, 9007199254740993.0}) {
        std::string text = formatFloat(x);
        INFO(text);
        CHECK(std::strtod(text.c_str(), nullptr) == x);
        CHECK(text.find_first_of(".e") != std::string::npos);
    }
}

TEST_CASE("quoted: writes escapes back") {
    CHECK(quoted("") == "\"\"");
    CHECK(quoted("plain") == "\"plain\"");
    CHECK(quoted("a\"b") == "\"a\\\"b\"");
    CHECK(quoted("back\\slash") == "\"back\\\\slash\"");
    CHECK(quoted("line\nbreak\ttab") == "\"line\\nbreak\\ttab\"");
    CHECK(quoted("é€") == "\"é€\"");
}

TEST_CASE("closestMatch: a plausible typo finds its word") {
    std::vector<std::string_view> attributes = {"center", "radius", "material"};
    CHECK(closestMatch("radus", attributes) == "radius");
    CHECK(closestMatch("raduis", attributes) == "radius");
    CHECK(closestMatch("centre", attributes) == "center");
    CHECK(closestMatch("materail", attributes) == "material");
    CHECK(closestMatch("radius", attributes) == "radius");
}

TEST_CASE("closestMatch: nothing close gives an empty string") {
    std::vector<std::string_view> attributes = {"center", "radius", "material"};
    CHECK(closestMatch("xyzzy", attributes) == "");
    CHECK(closestMatch("colour", attributes) == "");
    CHECK(closestMatch("radius", {}) == "");
}

TEST_CASE("values: the smallest int divided by -1 overflows, but its remainder is 0") {
    // -2^63 / -1 does not fit in 64 bits; -2^63 % -1 is 0 and fits.
    CHECK(contains(errorOf("m = -9223372036854775807 - 1\nx = m / -1\n"), "overflow"));
    CHECK(show("(-9223372036854775807 - 1) % -1") == "0");
}

TEST_CASE("values: a float index far outside the int range gets no fix-it") {
    // The fix-it casts the float to int64 without a range check: undefined behaviour for
    // 1e300 (UBSan: "1e+300 is outside the range of representable values of type 'long'"),
    // and in practice a suggestion of -9223372036854775808.
    EvalOptions options;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("v.crt", "x = [1.5][1e300]\n", options);
    REQUIRE(c.diagnostics.errorCount() == 1);
    CHECK(c.diagnostics.items()[0].fixits.empty());
    // A float that is an index gets a fix-it.
    Compilation d = compile("v.crt", "x = [1.5][0.0]\n", options);
    REQUIRE(d.diagnostics.errorCount() == 1);
    REQUIRE(d.diagnostics.items()[0].fixits.size() == 1);
    CHECK(d.diagnostics.items()[0].fixits[0].replacement == "0");
}

TEST_CASE("values: int ranges near the ends of the int range") {
    // The values are right, but computing a + i * s overflows in between (undefined
    // behaviour; UBSan reports builtins.cpp "2 * 9223372036854775807 cannot be represented").
    CHECK(show("range(-9223372036854775807 - 1, 9223372036854775807, 9223372036854775807)") ==
          "[-9223372036854775808, -1, 9223372036854775806]");
    CHECK(show("range(9223372036854775800, 9223372036854775807, 5)") ==
          "[9223372036854775800, 9223372036854775805]");
}

TEST_CASE("compile: an include from a script given by a bare file name") {
    // The including file's folder is "" for "v.crt"; fs::absolute("") throws
    // std::filesystem::filesystem_error out of compile() (crtc aborts) instead of searching
    // the current directory and reporting the missing file.
    EvalOptions options;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("v.crt", "include \"no_such_file_for_the_unit_test.crt\"\n", options);
    REQUIRE(c.diagnostics.errorCount() == 1);
    CHECK(contains(c.diagnostics.items()[0].message, "cannot find include file"));
}
