// Compiled Functions against the interpreter: random expressions of the arithmetic, the numeric
// built-ins, ?: and calls of other Functions give the same values through a Function's program
// as evaluated by the script, and folding constants or inlining calls changes none of them.
#include <catch2/catch.hpp>

#include "diagnostic.hpp"
#include "interpreter.hpp"

#include <fmt/format.h>

#include <random>
#include <sstream>
#include <string>

using namespace crt::lang;

namespace {

/// A random expression of x, y, z and float constants that the script evaluates without an
/// error (no comparison as a number, no square root of a negative, no int division).
class ExpressionMaker {
  public:
    explicit ExpressionMaker(uint64_t seed) : random_(seed) {}

    std::string make(int depth) {
        const int pick = depth <= 0 ? choose(0, 1) : choose(0, 9);
        switch (pick) {
        case 0: return std::string(1, "xyz"[choose(0, 2)]);
        case 1: return fmt::format("{:.3f}", std::uniform_real_distribution<double>(-3, 3)(random_));
        case 2: return fmt::format("({} {} {})", make(depth - 1), "+-*/"[choose(0, 3)], make(depth - 1));
        case 3: return fmt::format("-({})", make(depth - 1)); // "--" would start a comment
        case 4: {
            // floor, ceil and round give ints in a script, whose division is an int's: made
            // floats, as every number in a Function is.
            static constexpr const char* kUnary[] = {"sin", "cos", "atan", "abs", "floor", "ceil", "round"};
            const int which = choose(0, 6);
            const std::string call = fmt::format("{}({})", kUnary[which], make(depth - 1));
            return which >= 4 ? "(" + call + " * 1.0)" : call;
        }
        case 5: return fmt::format("sqrt(abs({}))", make(depth - 1));
        case 6: return fmt::format("{}({}, {}, {})", choose(0, 1) ? "min" : "max", make(depth - 1),
                                   make(depth - 1), make(depth - 1));
        case 7: return fmt::format("({} {} {} ? {} : {})", make(depth - 1), choose(0, 1) ? "<" : ">=",
                                   make(depth - 1), make(depth - 1), make(depth - 1));
        case 8: return fmt::format("atan2({}, {})", make(depth - 1), make(depth - 1));
        default: return fmt::format("mix({}, {}, {})", make(depth - 1), make(depth - 1), make(depth - 1));
        }
    }

  private:
    int choose(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random_); }
    std::mt19937_64 random_;
};

struct Run {
    std::string out;
    std::string firstError;
};

Run run(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("f.crt", text, options);
    Run r{out.str(), ""};
    for (const Diagnostic& d : c.diagnostics.items())
        if (d.severity == Severity::Error && r.firstError.empty()) r.firstError = d.message;
    return r;
}

} // namespace

TEST_CASE("a Function's program computes what the script computes, to the bit") {
    ExpressionMaker maker(7);
    std::string script = "x = 0.7\ny = -1.3\nz = 2.25\n";
    int count = 0;
    for (int i = 0; i < 300; ++i) {
        const std::string e = maker.make(4);
        // The script's value and the Function's, at the same point.
        script += fmt::format("f{} = Function (x, y, z) {{ {} }}\n", i, e);
        script += fmt::format("v{} = {}\n", i, e);
        script += fmt::format("print(v{} == f{}(x, y, z) ? \"same\" : str(v{}) + \" \" + str(f{}(x, y, z)))\n",
                              i, i, i, i);
        ++count;
    }
    // Calls of other Functions are inlined: the same values through two levels of calls.
    script += "g = Function (a, b, c) { f1(c, a, b) * f2(b, c, a) - f3(a, a, a) }\n";
    script += "h = Function (x, y, z) { g(y, z, x) + g(x, x, x) }\n";
    script += "print(h(x, y, z) == f1(x, y, z) * f2(z, x, y) - f3(y, y, y) + "
              "(f1(x, x, x) * f2(x, x, x) - f3(x, x, x)) ? \"same\" : \"differs\")\n";
    ++count;
    const Run r = run(script);
    INFO(r.firstError);
    REQUIRE(r.firstError.empty());
    std::istringstream lines(r.out);
    std::string line;
    int same = 0;
    while (std::getline(lines, line)) {
        INFO("line " << same + 1 << ": " << line);
        CHECK(line == "same");
        ++same;
    }
    CHECK(same == count);
}

TEST_CASE("a Function of many calls copied in is refused at the memory limit, not built") {
    // Each level calls the one below twice: 2^40 instructions if nothing stopped it.
    std::string script = "f0 = Function (x) { x * x + 1 }\n";
    for (int i = 1; i <= 40; ++i)
        script += fmt::format("f{} = Function (x) {{ f{}(x) + f{}(x + 1) }}\n", i, i - 1, i - 1);
    script += "print(f40(1))\n";
    EvalOptions options;
    options.checkFiles = false;
    options.limits.maxMemory = 64ull << 20;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("deep.crt", script, options);
    bool refused = false;
    for (const Diagnostic& d : c.diagnostics.items())
        refused = refused || (d.severity == Severity::Error && d.message.find("memory") != std::string::npos);
    CHECK(refused);
    CHECK(out.str().empty());
}
