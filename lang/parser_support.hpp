// Helpers for the grammar's actions and its token source; included only by the parser.
#pragma once

#include "parse_context.hpp"
#include "povray_habits.hpp"

#include <charconv>
#include <fmt/format.h>

namespace crt::lang::grammar {

int yylex(Parser::semantic_type* value, Parser::location_type* location, ParseContext& ctx);

inline Expr* makeBinary(ParseContext& ctx, BinaryOp op, Expr* left, SourceRange opRange,
                        Expr* right, SourceRange whole) {
    auto* n = ctx.node<BinaryExpr>(NodeKind::Binary, whole);
    n->op = op;
    n->opRange = opRange;
    n->left = left;
    n->right = right;
    return n;
}

inline Expr* makeUnary(ParseContext& ctx, UnaryOp op, SourceRange opRange, Expr* operand,
                       SourceRange whole) {
    auto* n = ctx.node<UnaryExpr>(NodeKind::Unary, whole);
    n->op = op;
    n->opRange = opRange;
    n->operand = operand;
    return n;
}

inline Expr* makeBool(ParseContext& ctx, bool value, SourceRange where) {
    auto* n = ctx.node<BoolLit>(NodeKind::BoolLit, where);
    n->value = value;
    return n;
}

inline Expr* makeAssign(ParseContext& ctx, Expr* target, Expr* value, SourceRange whole) {
    if (target->kind != NodeKind::Var) {
        std::string message =
            "cannot assign to this expression; the left of '=' must be a variable name";
        // `i++` on one line and an assignment on the next read as `i + (+next) = …`.
        const std::string_view text =
            ctx.file.text().substr(target->range.begin, target->range.end - target->range.begin);
        if (text.find("++") != std::string_view::npos)
            message += fmt::format("; {}", povray::kNoIncrement);
        ctx.diagnostics.error(target->range, std::move(message));
        return value;
    }
    auto* n = ctx.node<AssignExpr>(NodeKind::Assign, whole);
    n->name = static_cast<VarExpr*>(target)->name;
    n->nameRange = target->range;
    n->value = value;
    return n;
}

/// `x += v` is `x = x + v` (and -=, *=, /= likewise): the variable is read, then assigned,
/// so an undefined one is reported as for `x = x + v`.
inline Expr* makeCompoundAssign(ParseContext& ctx, BinaryOp op, Expr* target, SourceRange opRange,
                                Expr* value, SourceRange whole) {
    if (target->kind != NodeKind::Var) return makeAssign(ctx, target, value, whole);
    auto* read = ctx.node<VarExpr>(NodeKind::Var, target->range);
    read->name = static_cast<VarExpr*>(target)->name;
    return makeAssign(ctx, target, makeBinary(ctx, op, read, opRange, value, whole), whole);
}

/// `material m` or `matrix [...]` in a modifier list; any other name before an operand is
/// reported (a list of modifiers given by name stands alone: `<spin>`).
inline Modifier makeNamedModifier(ParseContext& ctx, std::string_view name, SourceRange nameRange,
                                  Expr* argument, SourceRange whole) {
    if (std::optional<ModifierOp> op = namedModifier(name)) return Modifier{*op, whole, argument};
    ctx.diagnostics.error(
        nameRange, fmt::format("'{}' is not a modifier; the modifiers are translate, rotate, "
                               "scale, material, matrix, shadow, camera and reflected, and lists of "
                               "them by name",
                               name));
    return Modifier{ModifierOp::Splice, whole, argument};
}

} // namespace crt::lang::grammar
