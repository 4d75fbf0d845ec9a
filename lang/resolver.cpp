// Name resolution: Python-like static scopes with macro closures.
#include "resolver.hpp"

#include "builtins.hpp"
#include "povray_habits.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace crt::lang {

uint32_t GlobalTable::slotFor(std::string_view name) {
    auto it = slots_.find(std::string(name));
    if (it != slots_.end()) return it->second;
    uint32_t slot = size();
    slots_.emplace(std::string(name), slot);
    entries_.push_back(Entry{std::string(name)});
    return slot;
}

const GlobalTable::Entry* GlobalTable::find(std::string_view name) const {
    auto it = slots_.find(std::string(name));
    return it == slots_.end() ? nullptr : &entries_[it->second];
}

namespace {

/// A macro body's scope: its parameters, then every name assigned in it.
struct MacroScope {
    MacroExpr* macro;
    struct Local {
        std::string_view name;
        SourceRange firstAssignment;
        bool isParameter = false;
        bool isLoopVariable = false;
        bool read = false;
    };
    std::vector<Local> locals;

    int find(std::string_view name) const {
        for (size_t i = 0; i < locals.size(); ++i) {
            if (locals[i].name == name) return static_cast<int>(i);
        }
        return -1;
    }
    void declare(std::string_view name, SourceRange where, bool loopVariable) {
        if (find(name) >= 0) return;
        locals.push_back({name, where, false, loopVariable, false});
    }
};

class Resolver {
public:
    Resolver(GlobalTable& globals, DiagnosticBag& diagnostics, bool isMainFile)
        : globals_(globals), diagnostics_(diagnostics), isMainFile_(isMainFile) {}

    ResolveResult run(Script& script) {
        // Top-level assignments are known before any use so a macro defined early can
        // read a global assigned later, and so a global shadows a built-in everywhere.
        for (Node* item : script.items) collectAssignments(item, nullptr);
        for (Node* item : script.items) visit(item);
        return result_;
    }

private:
    /// Declares the names `node` assigns, without entering nested macros. `scope` is null
    /// at the top level.
    void collectAssignments(Node* node, MacroScope* scope) {
        if (node->kind == NodeKind::Macro) return; // a nested macro is a scope of its own
        if (node->kind == NodeKind::Assign) {
            auto* a = static_cast<AssignExpr*>(node);
            declare(a->name, a->nameRange, scope, false);
        } else if (node->kind == NodeKind::For) {
            auto* f = static_cast<ForStmt*>(node);
            declare(f->variable, f->variableRange, scope, true);
        }
        forEachChild(node, [&](Node* child) { collectAssignments(child, scope); });
    }

    void declare(std::string_view name, SourceRange where, MacroScope* scope, bool loopVariable) {
        if (scope) {
            scope->declare(name, where, loopVariable);
            return;
        }
        uint32_t slot = globals_.slotFor(name);
        GlobalTable::Entry& entry = globals_.entry(slot);
        if (!entry.assigned) {
            entry.assigned = true;
            entry.firstAssignment = where;
            entry.reportUnused = isMainFile_ && !loopVariable;
        }
    }

    void warnIfShadowsBuiltin(std::string_view name, SourceRange where) {
        if (!findPreludeSlot(name)) return;
        for (std::string_view reported : shadowReported_) {
            if (reported == name) return;
        }
        shadowReported_.push_back(name);
        diagnostics_.warning(WarningKind::ShadowedBuiltin, where,
                             fmt::format("'{}' shadows the built-in of the same name", name));
    }

    Resolution lookup(std::string_view name, bool forRead) {
        if (forRead && !functions_.empty()) {
            const std::span<Param> params = functions_.back()->params;
            for (size_t i = 0; i < params.size(); ++i) {
                if (params[i].name == name) return {Binding::Parameter, 0, static_cast<uint32_t>(i)};
            }
        }
        for (size_t depth = 0; depth < scopes_.size(); ++depth) {
            MacroScope& scope = *scopes_[scopes_.size() - 1 - depth];
            int slot = scope.find(name);
            if (slot < 0) continue;
            if (forRead) scope.locals[static_cast<size_t>(slot)].read = true;
            // Every frame between here and the binding must outlive its call.
            for (size_t k = 1; k <= depth; ++k) scopes_[scopes_.size() - 1 - k]->macro->capturesFrame = true;
            return {depth == 0 ? Binding::Local : Binding::Enclosing, static_cast<uint16_t>(depth),
                    static_cast<uint32_t>(slot)};
        }
        const GlobalTable::Entry* global = globals_.find(name);
        if (!(global && global->assigned)) {
            if (auto prelude = findPreludeSlot(name)) {
                if (*prelude == preludeSlotOfT() || *prelude == preludeSlotOfClock()) {
                    result_.readsTime = true;
                }
                return {Binding::Builtin, 0, *prelude};
            }
        }
        uint32_t slot = globals_.slotFor(name);
        if (forRead) globals_.entry(slot).read = true;
        return {Binding::Global, 0, slot};
    }

    /// Resolves `node` and everything under it. Only the nodes that bind, read or check
    /// names need a case; the rest just pass the walk on to their children.
    void visit(Node* node) {
        switch (node->kind) {
        case NodeKind::Var: {
            auto* v = static_cast<VarExpr*>(node);
            v->resolution = lookup(v->name, true);
            break;
        }
        case NodeKind::Assign: {
            auto* a = static_cast<AssignExpr*>(node);
            visit(a->value);
            a->resolution = lookup(a->name, false);
            if (a->resolution.binding != Binding::Enclosing) warnIfShadowsBuiltin(a->name, a->nameRange);
            break;
        }
        case NodeKind::For: {
            auto* f = static_cast<ForStmt*>(node);
            visit(f->iterable);
            f->resolution = lookup(f->variable, false);
            if (f->resolution.binding != Binding::Enclosing) warnIfShadowsBuiltin(f->variable, f->variableRange);
            visit(f->body);
            break;
        }
        case NodeKind::Settings:
            attributes(objectInfo(ObjectType::Settings), static_cast<SettingsStmt*>(node)->attributes);
            break;
        case NodeKind::Object: object(static_cast<ObjectExpr*>(node)); break;
        case NodeKind::Macro: macro(static_cast<MacroExpr*>(node)); break;
        case NodeKind::Function: function(static_cast<FunctionExpr*>(node)); break;
        default: forEachChild(node, [&](Node* child) { visit(child); }); break;
        }
    }

    void object(ObjectExpr* node) {
        if (node->type == ObjectType::Count) {
            std::vector<std::string_view> names;
            for (const ObjectInfo& info : allObjectTypes()) {
                if (info.type != ObjectType::Settings) names.push_back(info.name);
            }
            std::string suggestion = closestMatch(node->typeName, names);
            Diagnostic& d = diagnostics_.error(
                node->typeRange, suggestion.empty()
                                     ? fmt::format("unknown object type '{}'", node->typeName)
                                     : fmt::format("unknown object type '{}'; did you mean '{}'?",
                                                   node->typeName, suggestion));
            if (!suggestion.empty()) d.fixits.push_back({node->typeRange, suggestion});
            for (Attribute& a : node->attributes) visit(a.value);
            return;
        }
        attributes(objectInfo(node->type), node->attributes);
    }

    void attributes(const ObjectInfo& info, std::span<Attribute> attrs) {
        for (size_t i = 0; i < attrs.size(); ++i) {
            Attribute& a = attrs[i];
            visit(a.value);
            a.slot = static_cast<int16_t>(findAttribute(info, a.name));
            if (a.slot < 0) {
                reportUnknownAttribute(info, a);
                continue;
            }
            for (size_t j = 0; j < i; ++j) {
                if (attrs[j].slot == a.slot && !attrs[j].overridden) {
                    attrs[j].overridden = true;
                    Diagnostic& d = diagnostics_.warning(
                        WarningKind::DuplicateAttribute, a.nameRange,
                        fmt::format("attribute '{}' of {} is given twice; this one wins", a.name,
                                    info.name));
                    d.notes.push_back({attrs[j].nameRange, "first given here"});
                }
            }
        }
    }

    void reportUnknownAttribute(const ObjectInfo& info, const Attribute& a) {
        std::vector<std::string_view> names;
        for (const AttributeInfo& attr : info.attributes) names.push_back(attr.name);
        std::string message = fmt::format("unknown attribute '{}' of {}", a.name, info.name);
        if (auto hint = povray::attributeHint(info.category, a.name)) {
            if (!hint->crtName.empty())
                message += fmt::format("; did you mean '{}'?", hint->crtName);
            Diagnostic& d = diagnostics_.error(a.nameRange, std::move(message));
            d.notes.push_back({a.nameRange, std::string(hint->note)});
            if (!hint->crtName.empty())
                d.fixits.push_back({a.nameRange, std::string(hint->crtName)});
            return;
        }
        std::string suggestion = closestMatch(a.name, names);
        if (!suggestion.empty()) message += fmt::format("; did you mean '{}'?", suggestion);
        Diagnostic& d = diagnostics_.error(a.nameRange, std::move(message));
        if (!suggestion.empty()) d.fixits.push_back({a.nameRange, suggestion});
    }

    void macro(MacroExpr* node) {
        MacroScope scope{node, {}};
        for (const Param& p : node->params) {
            if (scope.find(p.name) >= 0) {
                diagnostics_.error(p.range, fmt::format("parameter '{}' is listed twice", p.name));
                continue;
            }
            scope.locals.push_back({p.name, p.range, true, false, false});
        }
        for (Node* s : node->body->statements) collectAssignments(s, &scope);
        node->localCount = static_cast<uint32_t>(scope.locals.size());
        scopes_.push_back(&scope);
        visit(node->body);
        scopes_.pop_back();
        for (const MacroScope::Local& local : scope.locals) {
            if (!local.read && !local.isParameter && !local.isLoopVariable) {
                diagnostics_.warning(WarningKind::UnusedVariable, local.firstAssignment,
                                     fmt::format("variable '{}' is assigned but never used",
                                                 local.name));
            }
        }
    }

    /// A Function's parameters are its own; every other name in its body is read where the
    /// Function is made, so it resolves as it would beside the Function.
    void function(FunctionExpr* node) {
        for (size_t i = 0; i < node->params.size(); ++i) {
            for (size_t j = 0; j < i; ++j) {
                if (node->params[j].name == node->params[i].name) {
                    diagnostics_.error(node->params[i].range,
                                       fmt::format("parameter '{}' is listed twice", node->params[i].name));
                }
            }
        }
        functions_.push_back(node);
        visit(node->body);
        functions_.pop_back();
    }

    GlobalTable& globals_;
    DiagnosticBag& diagnostics_;
    std::vector<FunctionExpr*> functions_; ///< the Functions whose body the walk is in
    bool isMainFile_;
    std::vector<MacroScope*> scopes_;
    std::vector<std::string_view> shadowReported_;
    ResolveResult result_;
};

} // namespace

ResolveResult resolve(Script& script, GlobalTable& globals, DiagnosticBag& diagnostics,
                      bool isMainFile) {
    return Resolver(globals, diagnostics, isMainFile).run(script);
}

} // namespace crt::lang
