// The abstract syntax tree. Every node carries its source range; nodes live in an Arena and
// are never destroyed one by one, so they hold only trivially destructible members.
#pragma once

#include "arena.hpp"
#include "object_schema.hpp"
#include "source_file.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace crt::lang {

enum class NodeKind : uint8_t {
    // expressions
    IntLit,
    FloatLit,
    StringLit,
    BoolLit,
    Var,
    Assign,
    Unary,
    Binary,
    Ternary,
    Call,
    Index,
    Component,
    Modify,
    ModifierList,
    List,
    Object,
    Macro,
    Function,
    // statements
    While,
    For,
    If,
    Block,
    Settings,
    Scene,
    Include,
    Error, ///< what a syntax error left behind
};

enum class UnaryOp : uint8_t { Plus, Minus, Not };
enum class BinaryOp : uint8_t {
    Add, Sub, Intersect, Mul, Div, Mod, Less, Greater, LessEqual, GreaterEqual, Equal, NotEqual,
    And, Or,
};
/// Splice: a list of modifiers held in a value, given by name (`<spin>`). Material to
/// Reflected are words rather than keywords (they are names elsewhere).
enum class ModifierOp : uint8_t { Translate, Rotate, Scale, Material, Matrix, Shadow, Camera, Reflected, Splice };

std::string_view opSpelling(UnaryOp op);
std::string_view opSpelling(BinaryOp op);
std::string_view opSpelling(ModifierOp op);
/// The modifier a word names in a modifier list (`material`, `matrix`, `shadow`, `camera`,
/// `reflected`), if it is one of those words.
std::optional<ModifierOp> namedModifier(std::string_view word);

/// Where a name's value lives, decided once by the resolver.
enum class Binding : uint8_t {
    Unresolved,
    Global,    ///< slot in the global table
    Local,     ///< slot in the current macro frame
    Enclosing, ///< slot in the frame `depth` macro levels out
    Builtin,   ///< slot in the prelude (functions, t, clock)
    Parameter, ///< the parameter `slot` of the Function whose body holds the name
};

struct Resolution {
    Binding binding = Binding::Unresolved;
    uint16_t depth = 0;
    uint32_t slot = 0;
};

struct Node {
    NodeKind kind;
    SourceRange range;
};

struct Expr : Node {};

struct IntLit : Expr { int64_t value; };
struct FloatLit : Expr { double value; };
struct StringLit : Expr { std::string_view value; }; ///< escapes already decoded
struct BoolLit : Expr { bool value; };

struct VarExpr : Expr {
    std::string_view name;
    Resolution resolution;
};

struct AssignExpr : Expr {
    std::string_view name;
    SourceRange nameRange;
    Expr* value;
    Resolution resolution;
};

struct UnaryExpr : Expr {
    UnaryOp op;
    SourceRange opRange;
    Expr* operand;
};

struct BinaryExpr : Expr {
    BinaryOp op;
    SourceRange opRange;
    Expr* left;
    Expr* right;
};

struct TernaryExpr : Expr {
    Expr* condition;
    Expr* then;
    Expr* otherwise;
};

struct CallExpr : Expr {
    Expr* callee;
    std::span<Expr*> args;
};

struct IndexExpr : Expr {
    Expr* object;
    Expr* index;
};

/// `v.x`, `c.r`: one component of a vector or colour.
struct ComponentExpr : Expr {
    Expr* object;
    std::string_view name;
    SourceRange nameRange;
};

struct Modifier {
    ModifierOp op;
    SourceRange range; ///< the keyword and its argument
    Expr* argument;
};

struct ModifyExpr : Expr {
    Expr* target;
    std::span<Modifier> modifiers;
};

/// `<rotate v, translate w>` on its own: a list of modifiers as a value.
struct ModifierListExpr : Expr {
    std::span<Modifier> modifiers;
};

struct ListExpr : Expr {
    std::span<Expr*> items;
};

struct Attribute {
    std::string_view name;
    SourceRange nameRange;
    SourceRange range; ///< name through value
    Expr* value;
    int16_t slot;      ///< index in the object type's attribute table; -1 if unknown (resolver)
    bool overridden;   ///< a later attribute of the same name wins over this one (resolver)
};

struct ObjectExpr : Expr {
    std::string_view typeName;
    SourceRange typeRange;
    ObjectType type; ///< ObjectType::Count when the name is unknown
    std::span<Attribute> attributes;
};

struct Block;

struct Param {
    std::string_view name;
    SourceRange range;
};

struct MacroExpr : Expr {
    std::span<Param> params;
    Block* body;
    // Filled by the resolver:
    uint32_t localCount;  ///< params first, then other locals
    bool capturesFrame;   ///< a nested macro reads this frame's locals: it must outlive the call
};

/// `Function (x, y, z) { expression }`: a numeric function, compiled when it is made.
struct FunctionExpr : Expr {
    std::span<Param> params;
    Expr* body;
};

struct Block : Node {
    std::span<Node*> statements;
};

struct WhileStmt : Node {
    Expr* condition;
    Block* body;
};

struct ForStmt : Node {
    std::string_view variable;
    SourceRange variableRange;
    Resolution resolution;
    Expr* iterable;
    Block* body;
};

struct IfStmt : Node {
    Expr* condition;
    Block* then;
    Node* otherwise; ///< a Block, an IfStmt, or null
};

struct SettingsStmt : Node {
    std::span<Attribute> attributes;
};

struct SceneStmt : Node {
    std::span<Node*> statements;
};

struct IncludeStmt : Node {
    StringLit* path;
};

/// One parsed file.
struct Script {
    std::span<Node*> items;
    uint32_t file = 0;
};

inline bool isExpression(const Node* node) { return node->kind <= NodeKind::Function; }

/// Calls `visit` on each direct child of `node` in source order: operands, arguments,
/// attribute values, modifier arguments, statements, and a macro's body.
template <typename F> void forEachChild(Node* node, F&& visit) {
    auto each = [&](auto items) {
        for (Node* item : items) visit(item);
    };
    switch (node->kind) {
    case NodeKind::Assign: visit(static_cast<AssignExpr*>(node)->value); break;
    case NodeKind::Unary: visit(static_cast<UnaryExpr*>(node)->operand); break;
    case NodeKind::Binary:
        visit(static_cast<BinaryExpr*>(node)->left);
        visit(static_cast<BinaryExpr*>(node)->right);
        break;
    case NodeKind::Ternary: {
        auto* t = static_cast<TernaryExpr*>(node);
        visit(t->condition);
        visit(t->then);
        visit(t->otherwise);
        break;
    }
    case NodeKind::Call:
        visit(static_cast<CallExpr*>(node)->callee);
        each(static_cast<CallExpr*>(node)->args);
        break;
    case NodeKind::Index:
        visit(static_cast<IndexExpr*>(node)->object);
        visit(static_cast<IndexExpr*>(node)->index);
        break;
    case NodeKind::Component: visit(static_cast<ComponentExpr*>(node)->object); break;
    case NodeKind::Modify:
        visit(static_cast<ModifyExpr*>(node)->target);
        for (Modifier& m : static_cast<ModifyExpr*>(node)->modifiers) visit(m.argument);
        break;
    case NodeKind::ModifierList:
        for (Modifier& m : static_cast<ModifierListExpr*>(node)->modifiers) visit(m.argument);
        break;
    case NodeKind::List: each(static_cast<ListExpr*>(node)->items); break;
    case NodeKind::Object:
        for (Attribute& a : static_cast<ObjectExpr*>(node)->attributes) visit(a.value);
        break;
    case NodeKind::Macro: visit(static_cast<MacroExpr*>(node)->body); break;
    case NodeKind::Function: visit(static_cast<FunctionExpr*>(node)->body); break;
    case NodeKind::While:
        visit(static_cast<WhileStmt*>(node)->condition);
        visit(static_cast<WhileStmt*>(node)->body);
        break;
    case NodeKind::For:
        visit(static_cast<ForStmt*>(node)->iterable);
        visit(static_cast<ForStmt*>(node)->body);
        break;
    case NodeKind::If: {
        auto* i = static_cast<IfStmt*>(node);
        visit(i->condition);
        visit(i->then);
        if (i->otherwise) visit(i->otherwise);
        break;
    }
    case NodeKind::Block: each(static_cast<Block*>(node)->statements); break;
    case NodeKind::Settings:
        for (Attribute& a : static_cast<SettingsStmt*>(node)->attributes) visit(a.value);
        break;
    case NodeKind::Scene: each(static_cast<SceneStmt*>(node)->statements); break;
    case NodeKind::Include: visit(static_cast<IncludeStmt*>(node)->path); break;
    default: break; // literals, names, errors
    }
}

} // namespace crt::lang
