// A script's Function compiled to a small numeric program: register operations on doubles,
// run by the renderer on any thread without the interpreter, and by the interpreter for a
// call in a script.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace crt::scene {

/// What one instruction computes from its operand registers a, b and c. Comparisons and
/// logic give 1 or 0 and read any number but 0 as true.
enum class FunctionOp : uint8_t {
    Add, Sub, Mul, Div, Mod, Neg, Not,
    Less, Greater, LessEqual, GreaterEqual, Equal, NotEqual, And, Or,
    Select, ///< a ? b : c
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sqrt, Pow, Exp, Log, Abs, Floor, Ceil, Round,
    Min, Max, Clamp, Mix, Radians, Degrees,
};

/// How many operands each FunctionOp reads.
int functionOpArity(FunctionOp op);
/// Its name in the scene's JSON: "add", "sin", "select" …
std::string_view functionOpName(FunctionOp op);

struct FunctionInstruction {
    FunctionOp op;
    uint16_t out, a, b, c;
};

/// Registers are numbered: the parameters first, then the constants, then the temporaries.
/// Each instruction writes its `out`; the result is register `result` after the last.
struct FunctionProgram {
    std::vector<std::string> parameters; ///< their names, as the script wrote them
    std::vector<double> constants;
    std::vector<FunctionInstruction> code;
    uint32_t registerCount = 0;
    uint16_t result = 0;

    size_t parameterCount() const { return parameters.size(); }
    /// The value at `args` (one per parameter).
    double operator()(std::span<const double> args) const;
    /// The value at (x, y, z), for a Function of three parameters.
    double at(double x, double y, double z) const {
        const double args[3] = {x, y, z};
        return (*this)(args);
    }
};

/// The value of one instruction's operation on its operands (for folding constants).
double applyFunctionOp(FunctionOp op, double a, double b, double c);

} // namespace crt::scene
