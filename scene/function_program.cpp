// Running a compiled Function: one pass over its instructions.
#include "scene/function_program.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

namespace crt::scene {

int functionOpArity(FunctionOp op) {
    switch (op) {
    case FunctionOp::Neg: case FunctionOp::Not: case FunctionOp::Sin: case FunctionOp::Cos:
    case FunctionOp::Tan: case FunctionOp::Asin: case FunctionOp::Acos: case FunctionOp::Atan:
    case FunctionOp::Sqrt: case FunctionOp::Exp: case FunctionOp::Log: case FunctionOp::Abs:
    case FunctionOp::Floor: case FunctionOp::Ceil: case FunctionOp::Round:
    case FunctionOp::Radians: case FunctionOp::Degrees: return 1;
    case FunctionOp::Select: case FunctionOp::Clamp: case FunctionOp::Mix: return 3;
    default: return 2;
    }
}

std::string_view functionOpName(FunctionOp op) {
    static constexpr std::string_view kNames[] = {
        "add",   "sub",  "mul",  "div",  "mod",   "neg",   "not",   "less",  "greater",
        "lessequal", "greaterequal", "equal", "notequal", "and", "or", "select",
        "sin",   "cos",  "tan",  "asin", "acos",  "atan",  "atan2", "sqrt",  "pow",
        "exp",   "log",  "abs",  "floor", "ceil", "round", "min",   "max",   "clamp",
        "mix",   "radians", "degrees"};
    static_assert(std::size(kNames) == static_cast<size_t>(FunctionOp::Degrees) + 1);
    return kNames[static_cast<size_t>(op)];
}

double applyFunctionOp(FunctionOp op, double a, double b, double c) {
    switch (op) {
    case FunctionOp::Add: return a + b;
    case FunctionOp::Sub: return a - b;
    case FunctionOp::Mul: return a * b;
    case FunctionOp::Div: return a / b;
    case FunctionOp::Mod: return std::fmod(a, b);
    case FunctionOp::Neg: return -a;
    case FunctionOp::Not: return a == 0 ? 1 : 0;
    case FunctionOp::Less: return a < b ? 1 : 0;
    case FunctionOp::Greater: return a > b ? 1 : 0;
    case FunctionOp::LessEqual: return a <= b ? 1 : 0;
    case FunctionOp::GreaterEqual: return a >= b ? 1 : 0;
    case FunctionOp::Equal: return a == b ? 1 : 0;
    case FunctionOp::NotEqual: return a != b ? 1 : 0;
    case FunctionOp::And: return a != 0 && b != 0 ? 1 : 0;
    case FunctionOp::Or: return a != 0 || b != 0 ? 1 : 0;
    case FunctionOp::Select: return a != 0 ? b : c;
    case FunctionOp::Sin: return std::sin(a);
    case FunctionOp::Cos: return std::cos(a);
    case FunctionOp::Tan: return std::tan(a);
    case FunctionOp::Asin: return std::asin(a);
    case FunctionOp::Acos: return std::acos(a);
    case FunctionOp::Atan: return std::atan(a);
    case FunctionOp::Atan2: return std::atan2(a, b);
    case FunctionOp::Sqrt: return std::sqrt(a);
    case FunctionOp::Pow: return std::pow(a, b);
    case FunctionOp::Exp: return std::exp(a);
    case FunctionOp::Log: return std::log(a);
    case FunctionOp::Abs: return std::abs(a);
    case FunctionOp::Floor: return std::floor(a);
    case FunctionOp::Ceil: return std::ceil(a);
    case FunctionOp::Round: return std::round(a);
    case FunctionOp::Min: return std::min(a, b);
    case FunctionOp::Max: return std::max(a, b);
    case FunctionOp::Clamp: return std::min(std::max(a, b), c);
    case FunctionOp::Mix: return a + (b - a) * c;
    case FunctionOp::Radians: return a * (std::numbers::pi / 180);
    case FunctionOp::Degrees: return a * (180 / std::numbers::pi);
    }
    return 0;
}

namespace {

/// The program on registers `r`, whose parameters and constants are in place.
double run(const FunctionProgram& program, double* r) {
    for (const FunctionInstruction& in : program.code) {
        // The common operations inline; the rest through applyFunctionOp.
        switch (in.op) {
        case FunctionOp::Add: r[in.out] = r[in.a] + r[in.b]; break;
        case FunctionOp::Sub: r[in.out] = r[in.a] - r[in.b]; break;
        case FunctionOp::Mul: r[in.out] = r[in.a] * r[in.b]; break;
        case FunctionOp::Div: r[in.out] = r[in.a] / r[in.b]; break;
        case FunctionOp::Neg: r[in.out] = -r[in.a]; break;
        case FunctionOp::Min: r[in.out] = std::min(r[in.a], r[in.b]); break;
        case FunctionOp::Max: r[in.out] = std::max(r[in.a], r[in.b]); break;
        case FunctionOp::Abs: r[in.out] = std::abs(r[in.a]); break;
        case FunctionOp::Sqrt: r[in.out] = std::sqrt(r[in.a]); break;
        case FunctionOp::Select: r[in.out] = r[in.a] != 0 ? r[in.b] : r[in.c]; break;
        case FunctionOp::Sin: r[in.out] = std::sin(r[in.a]); break;
        case FunctionOp::Cos: r[in.out] = std::cos(r[in.a]); break;
        default: r[in.out] = applyFunctionOp(in.op, r[in.a], r[in.b], r[in.c]); break;
        }
    }
    return r[program.result];
}

} // namespace

double FunctionProgram::operator()(std::span<const double> args) const {
    constexpr size_t kInPlace = 64;
    std::array<double, kInPlace> inPlace;
    std::vector<double> onHeap;
    double* r = inPlace.data();
    if (registerCount > kInPlace) {
        onHeap.resize(registerCount);
        r = onHeap.data();
    }
    // Element by element: a handful each, where a call of memmove would cost more.
    const size_t n = std::min(args.size(), parameters.size());
    for (size_t i = 0; i < parameters.size(); ++i) r[i] = i < n ? args[i] : 0.0;
    double* k = r + parameters.size();
    for (size_t i = 0; i < constants.size(); ++i) k[i] = constants[i];
    return run(*this, r);
}

} // namespace crt::scene
