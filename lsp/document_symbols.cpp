// Builds the outline from the AST: what a reader looks for in a scene file.
#include "document_symbols.hpp"

#include "large_stack.hpp"

#include <fmt/format.h>

namespace crt::lsp {

using namespace lang;

namespace {

class Outliner {
public:
    explicit Outliner(const Analysis& a) : a_(a) {}

    /// Appends the symbols of `node` (a statement or expression) to `out`.
    void node(const Node* n, std::vector<DocumentSymbol>& out) {
        if (n->range.file != 0) return;
        switch (n->kind) {
        case NodeKind::Assign: {
            auto* as = static_cast<const AssignExpr*>(n);
            DocumentSymbol s{std::string(as->name), staticType(as->value), OutlineKind::Variable,
                             as->range, as->nameRange, {}};
            value(as->value, s);
            out.push_back(std::move(s));
            return;
        }
        case NodeKind::Object: {
            auto* o = static_cast<const ObjectExpr*>(n);
            DocumentSymbol s{std::string(o->typeName), "", OutlineKind::Object, o->range, o->typeRange, {}};
            attributes(o->attributes, s.children);
            out.push_back(std::move(s));
            return;
        }
        case NodeKind::Settings: {
            auto* st = static_cast<const SettingsStmt*>(n);
            DocumentSymbol s{"Settings", "", OutlineKind::Namespace, st->range, {0, st->range.begin, st->range.begin + 8}, {}};
            attributes(st->attributes, s.children);
            out.push_back(std::move(s));
            return;
        }
        case NodeKind::Scene: {
            auto* sc = static_cast<const SceneStmt*>(n);
            DocumentSymbol s{"Scene", "", OutlineKind::Namespace, sc->range, {0, sc->range.begin, sc->range.begin + 5}, {}};
            for (const Node* child : sc->statements) node(child, s.children);
            out.push_back(std::move(s));
            return;
        }
        case NodeKind::Include: {
            auto* inc = static_cast<const IncludeStmt*>(n);
            out.push_back({fmt::format("include \"{}\"", inc->path->value), "", OutlineKind::File, inc->range,
                           inc->path->range, {}});
            return;
        }
        case NodeKind::Modify: node(static_cast<const ModifyExpr*>(n)->target, out); return;
        case NodeKind::Binary: case NodeKind::Call: case NodeKind::List: case NodeKind::While:
        case NodeKind::For: case NodeKind::If: case NodeKind::Block:
            // Objects and assignments inside loops and expressions still belong to the outline.
            forEachChild(const_cast<Node*>(n), [&](Node* child) { node(child, out); });
            return;
        default: return;
        }
    }

private:
    void value(const Expr* v, DocumentSymbol& s) {
        if (v->kind == NodeKind::Macro) {
            auto* m = static_cast<const MacroExpr*>(v);
            s.kind = OutlineKind::Function;
            for (const Node* statement : m->body->statements) node(statement, s.children);
        } else if (v->kind == NodeKind::Object) {
            auto* o = static_cast<const ObjectExpr*>(v);
            s.kind = OutlineKind::Object;
            attributes(o->attributes, s.children);
        } else if (v->kind == NodeKind::Modify || v->kind == NodeKind::Binary || v->kind == NodeKind::List) {
            s.kind = OutlineKind::Object;
            forEachChild(const_cast<Expr*>(v), [&](Node* child) { node(child, s.children); });
        }
    }

    void attributes(std::span<const Attribute> attrs, std::vector<DocumentSymbol>& out) {
        for (const Attribute& attr : attrs) {
            std::string_view text = a_.text(attr.value->range);
            std::string detail(text.substr(0, std::min<size_t>(text.find('\n'), 60)));
            DocumentSymbol s{std::string(attr.name), detail, OutlineKind::Property, attr.range, attr.nameRange, {}};
            if (attr.value->kind == NodeKind::Object || attr.value->kind == NodeKind::Macro) value(attr.value, s);
            out.push_back(std::move(s));
        }
    }

    const Analysis& a_;
};

} // namespace

std::vector<DocumentSymbol> documentSymbols(const Analysis& a) {
    std::vector<DocumentSymbol> result;
    Outliner outliner(a);
    runOnLargeStack([&] { // the walk recurses into expressions, which may nest deeply
        for (const Node* item : a.script().items) outliner.node(item, result);
    });
    return result;
}

} // namespace crt::lsp
