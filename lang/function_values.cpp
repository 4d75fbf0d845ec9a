// Function values: `Function (x, y, z) { expression }` compiled into a scene::FunctionProgram
// when it is made, and called from scripts.
#include "interpreter_impl.hpp"

#include <bit>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace crt::lang {

namespace {

using scene::FunctionOp;

/// The Function operation of a numeric built-in, by name; nullopt for the others.
std::optional<FunctionOp> builtinOp(std::string_view name) {
    static const std::unordered_map<std::string_view, FunctionOp> kOps = {
        {"sin", FunctionOp::Sin},         {"cos", FunctionOp::Cos},
        {"tan", FunctionOp::Tan},         {"asin", FunctionOp::Asin},
        {"acos", FunctionOp::Acos},       {"atan", FunctionOp::Atan},
        {"atan2", FunctionOp::Atan2},     {"sqrt", FunctionOp::Sqrt},
        {"pow", FunctionOp::Pow},         {"exp", FunctionOp::Exp},
        {"log", FunctionOp::Log},         {"abs", FunctionOp::Abs},
        {"floor", FunctionOp::Floor},     {"ceil", FunctionOp::Ceil},
        {"round", FunctionOp::Round},     {"min", FunctionOp::Min},
        {"max", FunctionOp::Max},         {"clamp", FunctionOp::Clamp},
        {"mix", FunctionOp::Mix},         {"radians", FunctionOp::Radians},
        {"degrees", FunctionOp::Degrees},
    };
    auto it = kOps.find(name);
    return it == kOps.end() ? std::nullopt : std::optional(it->second);
}

/// The numeric built-ins' names, for messages.
constexpr std::string_view kNumericBuiltins =
    "sin, cos, tan, asin, acos, atan, atan2, sqrt, pow, exp, log, abs, floor, ceil, round, min, "
    "max, clamp, mix, radians and degrees";

/// What a node that a Function cannot hold is, for its error.
std::string_view describe(NodeKind kind) {
    switch (kind) {
    case NodeKind::StringLit: return "a string";
    case NodeKind::Assign: return "an assignment";
    case NodeKind::Index: return "an index";
    case NodeKind::Modify:
    case NodeKind::ModifierList: return "modifiers";
    case NodeKind::List: return "a list";
    case NodeKind::Object: return "an object";
    case NodeKind::Macro: return "a Macro";
    case NodeKind::Function: return "a Function literal";
    default: return "this";
    }
}

} // namespace

/// Compiles one Function's body. Operands are numbered in three spaces while compiling
/// (parameters, constants, temporaries) and renumbered into one register file at the end.
class FunctionCompiler {
  public:
    FunctionCompiler(Interpreter& in, const FunctionExpr* node) : in_(in), node_(node) {}

    scene::FunctionProgram compile() {
        Operand result = expr(node_->body);
        dropUnusedConstants(result);
        scene::FunctionProgram program;
        for (const Param& p : node_->params) program.parameters.emplace_back(p.name);
        program.constants = std::move(constants_);
        const uint32_t temporariesAt = static_cast<uint32_t>(program.parameters.size() + program.constants.size());
        const uint32_t registers = temporariesAt + temporaryHigh_;
        if (registers > 0xFFFF) {
            in_.fail(node_->range, fmt::format("this Function needs {} registers, more than the "
                                               "65,535 a Function may use; split it into smaller Functions",
                                               registers));
        }
        auto number = [&](Operand o) -> uint16_t {
            const uint32_t base = o.space == Space::Parameter ? 0
                                  : o.space == Space::Constant
                                      ? static_cast<uint32_t>(program.parameters.size())
                                      : temporariesAt;
            return static_cast<uint16_t>(base + o.index);
        };
        program.code.reserve(code_.size());
        for (const Pending& p : code_)
            program.code.push_back({p.op, number(p.out), number(p.a), number(p.b), number(p.c)});
        program.registerCount = registers;
        program.result = number(result);
        return program;
    }

  private:
    enum class Space : uint8_t { Parameter, Constant, Temporary };
    struct Operand {
        Space space;
        uint32_t index;
    };
    struct Pending {
        FunctionOp op;
        Operand out, a, b, c;
    };

    /// Constants folded into others (r in r * r) need no register.
    void dropUnusedConstants(Operand& result) {
        std::vector<uint32_t> renumbered(constants_.size(), UINT32_MAX);
        std::vector<double> kept;
        auto keep = [&](Operand& o) {
            if (o.space != Space::Constant) return;
            if (renumbered[o.index] == UINT32_MAX) {
                renumbered[o.index] = static_cast<uint32_t>(kept.size());
                kept.push_back(constants_[o.index]);
            }
            o.index = renumbered[o.index];
        };
        for (Pending& p : code_) {
            for (Operand* o : {&p.a, &p.b, &p.c}) keep(*o);
        }
        keep(result);
        constants_ = std::move(kept);
    }

    Operand constant(double value) {
        // The same bits share a register (0 and -0 stay apart).
        const uint64_t bits = std::bit_cast<uint64_t>(value);
        auto [it, added] = constantIndex_.try_emplace(bits, static_cast<uint32_t>(constants_.size()));
        if (added) constants_.push_back(value);
        return {Space::Constant, it->second};
    }

    /// The value of `op` on its operands: folded when they are all constants, else computed
    /// by a new instruction into the first free temporary.
    Operand apply(FunctionOp op, Operand a, Operand b, Operand c, uint32_t freeFrom) {
        const int arity = scene::functionOpArity(op);
        if (arity < 3) c = a;
        if (arity < 2) b = a;
        if (a.space == Space::Constant && b.space == Space::Constant && c.space == Space::Constant)
            return constant(scene::applyFunctionOp(op, constants_[a.index], constants_[b.index],
                                                   constants_[c.index]));
        const Operand out{Space::Temporary, freeFrom};
        temporaryTop_ = freeFrom + 1;
        temporaryHigh_ = std::max(temporaryHigh_, temporaryTop_);
        in_.charge(sizeof(Pending) + sizeof(scene::FunctionInstruction)); // now, and in the program
        code_.push_back({op, out, a, b, c});
        return out;
    }

    [[noreturn]] void refuse(const Node* node, std::string_view what) {
        in_.fail(node->range, fmt::format("a Function cannot hold {}: only numbers, names of numbers, "
                                          "arithmetic, comparisons, ?:, the numeric built-ins and "
                                          "calls of other Functions",
                                          what));
    }

    /// Compiles `node`; its value is the operand returned, and the temporaries from the one
    /// free before up to that operand's are in use.
    Operand expr(const Expr* node) {
        Interpreter::NestingLevel level(in_, node);
        const uint32_t freeFrom = temporaryTop_;
        switch (node->kind) {
        case NodeKind::IntLit: return constant(static_cast<double>(static_cast<const IntLit*>(node)->value));
        case NodeKind::FloatLit: return constant(static_cast<const FloatLit*>(node)->value);
        case NodeKind::BoolLit: return constant(static_cast<const BoolLit*>(node)->value ? 1 : 0);
        case NodeKind::Var: return variable(static_cast<const VarExpr*>(node));
        case NodeKind::Unary: {
            auto* u = static_cast<const UnaryExpr*>(node);
            const Operand a = expr(u->operand);
            if (u->op == UnaryOp::Plus) return a;
            return apply(u->op == UnaryOp::Minus ? FunctionOp::Neg : FunctionOp::Not, a, a, a, freeFrom);
        }
        case NodeKind::Binary: return binary(static_cast<const BinaryExpr*>(node), freeFrom);
        case NodeKind::Ternary: {
            auto* t = static_cast<const TernaryExpr*>(node);
            const Operand c = expr(t->condition);
            const Operand a = expr(t->then);
            const Operand b = expr(t->otherwise);
            return apply(FunctionOp::Select, c, a, b, freeFrom);
        }
        case NodeKind::Call: return call(static_cast<const CallExpr*>(node), freeFrom);
        case NodeKind::Component: {
            auto* c = static_cast<const ComponentExpr*>(node);
            if (c->object->kind != NodeKind::Var ||
                static_cast<const VarExpr*>(c->object)->resolution.binding == Binding::Parameter)
                refuse(node, "a component of anything but a named vec3 or colour");
            return number(in_.eval(node), node);
        }
        default: refuse(node, describe(node->kind));
        }
    }

    Operand variable(const VarExpr* node) {
        if (node->resolution.binding == Binding::Parameter) return {Space::Parameter, node->resolution.slot};
        const Value value = in_.evalVar(node);
        if (value.kind == ValueKind::Function || value.kind == ValueKind::Builtin)
            in_.fail(node->range, fmt::format("'{}' is a function: call it here, as {}(…)", node->name, node->name));
        return number(value, node);
    }

    /// A value read when the Function is made, which must be a number.
    Operand number(const Value& value, const Node* node) {
        if (value.isNumber()) return constant(value.asDouble());
        if (value.kind == ValueKind::Bool) return constant(value.b ? 1 : 0);
        in_.fail(node->range, fmt::format("a Function computes with numbers, and this is {} {}",
                                          startsWithVowel(typeName(value)) ? "an" : "a", typeName(value)));
    }
    static bool startsWithVowel(const std::string& word) {
        return !word.empty() && std::string_view("aeiouAEIOU").find(word[0]) != std::string_view::npos;
    }

    Operand binary(const BinaryExpr* node, uint32_t freeFrom) {
        static constexpr std::pair<BinaryOp, FunctionOp> kOps[] = {
            {BinaryOp::Add, FunctionOp::Add},           {BinaryOp::Sub, FunctionOp::Sub},
            {BinaryOp::Mul, FunctionOp::Mul},           {BinaryOp::Div, FunctionOp::Div},
            {BinaryOp::Mod, FunctionOp::Mod},           {BinaryOp::Less, FunctionOp::Less},
            {BinaryOp::Greater, FunctionOp::Greater},   {BinaryOp::LessEqual, FunctionOp::LessEqual},
            {BinaryOp::GreaterEqual, FunctionOp::GreaterEqual}, {BinaryOp::Equal, FunctionOp::Equal},
            {BinaryOp::NotEqual, FunctionOp::NotEqual}, {BinaryOp::And, FunctionOp::And},
            {BinaryOp::Or, FunctionOp::Or},
        };
        const Operand a = expr(node->left);
        const Operand b = expr(node->right);
        for (auto [from, to] : kOps)
            if (from == node->op) return apply(to, a, b, b, freeFrom);
        in_.fail(node->opRange, "'^' in a Function: it is the intersection of solids; write pow(a, b) for a power");
    }

    Operand call(const CallExpr* node, uint32_t freeFrom) {
        const auto* name = node->callee->kind == NodeKind::Var ? static_cast<const VarExpr*>(node->callee) : nullptr;
        if (!name || name->resolution.binding == Binding::Parameter)
            refuse(node, "a call of anything but a built-in or a Function by its name");
        const Value callee = in_.evalVar(name);
        if (callee.kind == ValueKind::Function) return inlineCall(node, callee.index, freeFrom);
        if (callee.kind != ValueKind::Builtin) refuse(node, fmt::format("a call of a {}", typeName(callee)));
        const BuiltinInfo& info = builtinFunctions()[callee.index];
        const std::optional<FunctionOp> op = builtinOp(info.name);
        if (!op)
            in_.fail(node->callee->range, fmt::format("'{}' cannot be called in a Function; the numeric "
                                                      "built-ins are {}", info.name, kNumericBuiltins));
        if (!Interpreter::arityFits(info, node->args.size())) in_.arityError(info, node);
        std::vector<Operand> args;
        for (const Expr* arg : node->args) args.push_back(expr(arg));
        if (*op == FunctionOp::Min || *op == FunctionOp::Max) {
            // Each step above every argument, so that none is written over before it is read.
            Operand folded = args[0];
            for (size_t i = 1; i < args.size(); ++i) folded = apply(*op, folded, args[i], args[i], temporaryTop_);
            return folded;
        }
        // A square, the commonest power in isosurfaces, is one product rather than a call of pow.
        if (*op == FunctionOp::Pow && args[1].space == Space::Constant && constants_[args[1].index] == 2)
            return apply(FunctionOp::Mul, args[0], args[0], args[0], freeFrom);
        args.resize(3, args[0]);
        return apply(*op, args[0], args[1], args[2], freeFrom);
    }

    /// Another Function's program, copied in with its parameters bound to the arguments.
    Operand inlineCall(const CallExpr* node, uint32_t index, uint32_t freeFrom) {
        const scene::FunctionProgram& callee = *in_.functionProgram(index);
        if (node->args.size() != callee.parameterCount()) {
            in_.fail(node->range, fmt::format("this Function takes {} argument{}, but {} {} given",
                                              callee.parameterCount(), callee.parameterCount() == 1 ? "" : "s",
                                              node->args.size(), node->args.size() == 1 ? "was" : "were"));
        }
        // What each of the callee's registers holds here: the arguments, the constants, and
        // its temporaries, which go one to one above the arguments' (or fold to constants).
        std::vector<Operand> registers;
        for (const Expr* arg : node->args) registers.push_back(expr(arg));
        for (double c : callee.constants) registers.push_back(constant(c));
        const uint32_t calleeTemporaries = static_cast<uint32_t>(registers.size());
        const uint32_t base = temporaryTop_;
        registers.resize(callee.registerCount, Operand{Space::Temporary, base});
        for (const scene::FunctionInstruction& in : callee.code) {
            registers[in.out] = apply(in.op, registers[in.a], registers[in.b], registers[in.c],
                                      base + (in.out - calleeTemporaries));
        }
        const Operand result = registers[callee.result];
        temporaryTop_ = result.space == Space::Temporary ? result.index + 1 : freeFrom;
        return result;
    }

    Interpreter& in_;
    const FunctionExpr* node_;
    std::vector<double> constants_;
    std::unordered_map<uint64_t, uint32_t> constantIndex_;
    std::vector<Pending> code_;
    uint32_t temporaryTop_ = 0;  ///< the first temporary free
    uint32_t temporaryHigh_ = 0; ///< how many temporaries the program uses
};

Value Interpreter::evalFunction(const FunctionExpr* node) {
    auto program = std::make_shared<scene::FunctionProgram>(FunctionCompiler(*this, node).compile());
    functions_.push_back({std::move(program), span(node->range)});
    return Value::object(ValueKind::Function, ObjectType::Count, static_cast<uint32_t>(functions_.size() - 1));
}

Value Interpreter::callFunction(uint32_t index, const CallExpr* site, std::span<const Value> args) {
    const scene::FunctionProgram& program = *functions_[index].program;
    if (args.size() != program.parameterCount()) {
        fail(site->range, fmt::format("this Function takes {} argument{}, but {} {} given",
                                      program.parameterCount(), program.parameterCount() == 1 ? "" : "s",
                                      args.size(), args.size() == 1 ? "was" : "were"));
    }
    std::vector<double> numbers;
    for (size_t i = 0; i < args.size(); ++i) {
        if (!args[i].isNumber())
            fail(argRange(site, i), fmt::format("a Function takes numbers, and this is {}", typeName(args[i])));
        numbers.push_back(args[i].asDouble());
    }
    step(site->range);
    return Value::number(program(numbers));
}

} // namespace crt::lang
