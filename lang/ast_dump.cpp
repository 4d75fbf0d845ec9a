// Indented text dump of the AST.
#include "ast_dump.hpp"

#include "value_format.hpp"

#include <fmt/format.h>

namespace crt::lang {
namespace {

class Dumper {
public:
    explicit Dumper(const SourceFile& file) : file_(file) {}

    void node(const Node* n, int depth) {
        if (!n) return;
        if (isExpression(n)) expression(n, depth);
        else statement(n, depth);
    }

    void statements(std::span<Node* const> items, int depth) {
        for (const Node* item : items) node(item, depth);
    }

    std::string out_;

private:
    void expression(const Node* n, int depth) {
        switch (n->kind) {
        case NodeKind::IntLit: line(n, depth, fmt::format("Int {}", static_cast<const IntLit*>(n)->value)); break;
        case NodeKind::FloatLit: line(n, depth, fmt::format("Float {}", formatFloat(static_cast<const FloatLit*>(n)->value))); break;
        case NodeKind::StringLit: line(n, depth, fmt::format("String {}", quoted(static_cast<const StringLit*>(n)->value))); break;
        case NodeKind::BoolLit: line(n, depth, static_cast<const BoolLit*>(n)->value ? "Bool true" : "Bool false"); break;
        case NodeKind::Var: line(n, depth, fmt::format("Var {}", static_cast<const VarExpr*>(n)->name)); break;
        case NodeKind::Assign: {
            auto* a = static_cast<const AssignExpr*>(n);
            line(n, depth, fmt::format("Assign {}", a->name));
            node(a->value, depth + 1);
            break;
        }
        case NodeKind::Unary: {
            auto* u = static_cast<const UnaryExpr*>(n);
            line(n, depth, fmt::format("Unary {}", opSpelling(u->op)));
            node(u->operand, depth + 1);
            break;
        }
        case NodeKind::Binary: {
            auto* b = static_cast<const BinaryExpr*>(n);
            line(n, depth, fmt::format("Binary {}", opSpelling(b->op)));
            node(b->left, depth + 1);
            node(b->right, depth + 1);
            break;
        }
        case NodeKind::Ternary: {
            auto* t = static_cast<const TernaryExpr*>(n);
            line(n, depth, "Ternary");
            node(t->condition, depth + 1);
            node(t->then, depth + 1);
            node(t->otherwise, depth + 1);
            break;
        }
        case NodeKind::Call: {
            auto* c = static_cast<const CallExpr*>(n);
            line(n, depth, fmt::format("Call ({} arguments)", c->args.size()));
            node(c->callee, depth + 1);
            for (const Expr* arg : c->args) node(arg, depth + 1);
            break;
        }
        case NodeKind::Index: {
            auto* i = static_cast<const IndexExpr*>(n);
            line(n, depth, "Index");
            node(i->object, depth + 1);
            node(i->index, depth + 1);
            break;
        }
        case NodeKind::Component: {
            auto* c = static_cast<const ComponentExpr*>(n);
            line(n, depth, fmt::format("Component {}", c->name));
            node(c->object, depth + 1);
            break;
        }
        case NodeKind::Modify: {
            auto* m = static_cast<const ModifyExpr*>(n);
            line(n, depth, "Modify");
            node(m->target, depth + 1);
            modifiers(m->modifiers, depth + 1);
            break;
        }
        case NodeKind::ModifierList:
            line(n, depth, "ModifierList");
            modifiers(static_cast<const ModifierListExpr*>(n)->modifiers, depth + 1);
            break;
        case NodeKind::List: {
            auto* l = static_cast<const ListExpr*>(n);
            line(n, depth, fmt::format("List ({} items)", l->items.size()));
            for (const Expr* item : l->items) node(item, depth + 1);
            break;
        }
        case NodeKind::Object: {
            auto* o = static_cast<const ObjectExpr*>(n);
            line(n, depth, fmt::format("Object {}", o->typeName));
            attributes(o->attributes, depth + 1);
            break;
        }
        case NodeKind::Macro: {
            auto* m = static_cast<const MacroExpr*>(n);
            std::string params;
            for (const Param& p : m->params) params += (params.empty() ? "" : ", ") + std::string(p.name);
            line(n, depth, fmt::format("Macro ({})", params));
            statements(m->body->statements, depth + 1);
            break;
        }
        case NodeKind::Function: {
            auto* f = static_cast<const FunctionExpr*>(n);
            std::string params;
            for (const Param& p : f->params) params += (params.empty() ? "" : ", ") + std::string(p.name);
            line(n, depth, fmt::format("Function ({})", params));
            node(f->body, depth + 1);
            break;
        }
        default: break;
        }
    }

    void statement(const Node* n, int depth) {
        switch (n->kind) {
        case NodeKind::While: {
            auto* w = static_cast<const WhileStmt*>(n);
            line(n, depth, "While");
            node(w->condition, depth + 1);
            node(w->body, depth + 1);
            break;
        }
        case NodeKind::For: {
            auto* f = static_cast<const ForStmt*>(n);
            line(n, depth, fmt::format("For {}", f->variable));
            node(f->iterable, depth + 1);
            node(f->body, depth + 1);
            break;
        }
        case NodeKind::If: {
            auto* i = static_cast<const IfStmt*>(n);
            line(n, depth, "If");
            node(i->condition, depth + 1);
            node(i->then, depth + 1);
            if (i->otherwise) {
                indent(depth);
                out_ += "Else\n";
                node(i->otherwise, depth + 1);
            }
            break;
        }
        case NodeKind::Block:
            line(n, depth, "Block");
            statements(static_cast<const Block*>(n)->statements, depth + 1);
            break;
        case NodeKind::Settings:
            line(n, depth, "Settings");
            attributes(static_cast<const SettingsStmt*>(n)->attributes, depth + 1);
            break;
        case NodeKind::Scene:
            line(n, depth, "Scene");
            statements(static_cast<const SceneStmt*>(n)->statements, depth + 1);
            break;
        case NodeKind::Include:
            line(n, depth, fmt::format("Include {}", quoted(static_cast<const IncludeStmt*>(n)->path->value)));
            break;
        case NodeKind::Error: line(n, depth, "Error"); break;
        default: break;
        }
    }

    void modifiers(std::span<const Modifier> modifiers, int depth) {
        for (const Modifier& mod : modifiers) {
            text(mod.range, depth,
                 mod.op == ModifierOp::Splice ? std::string("Modifier list")
                                              : fmt::format("Modifier {}", opSpelling(mod.op)));
            node(mod.argument, depth + 1);
        }
    }

    void attributes(std::span<const Attribute> attrs, int depth) {
        for (const Attribute& a : attrs) {
            text(a.range, depth, fmt::format("Attribute {}", a.name));
            node(a.value, depth + 1);
        }
    }
    void indent(int depth) {
        // Past kMaxIndent levels the depth is written as a number: indenting every line of a
        // tree 100,000 levels deep by its depth would make the dump quadratic in its size.
        constexpr int kMaxIndent = 100;
        if (depth <= kMaxIndent) {
            out_.append(static_cast<size_t>(depth) * 2, ' ');
        } else {
            out_.append(static_cast<size_t>(kMaxIndent) * 2, ' ');
            out_ += fmt::format("[{}] ", depth);
        }
    }
    void line(const Node* n, int depth, std::string_view what) { text(n->range, depth, what); }
    void text(SourceRange range, int depth, std::string_view what) {
        indent(depth);
        LineColumn begin = file_.lineColumn(range.begin);
        LineColumn end = file_.lineColumn(range.end);
        out_ += fmt::format("{} <{}:{}-{}:{}>\n", what, begin.line, begin.column, end.line, end.column);
    }

    const SourceFile& file_;
};

} // namespace

std::string dumpAst(const Script& script, const SourceFile& file) {
    Dumper dumper(file);
    dumper.out_ = "Script\n";
    dumper.statements(script.items, 1);
    return std::move(dumper.out_);
}

} // namespace crt::lang
