// Runs the front end for the editor and indexes names, attributes and included files.
#include "analysis.hpp"

#include "builtins.hpp"
#include "large_stack.hpp"
#include "parser.hpp"
#include "resolver.hpp"
#include "terminal_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace crt::lsp {

namespace fs = std::filesystem;
using namespace lang;

// ---------------------------------------------------------------- includes

std::string findInclude(const std::string& name, const std::string& folder,
                        const AnalysisOptions& options, const FileAccess& access) {
    fs::path found = options.includes.find(name, folder, access).path;
    return found.empty() ? std::string() : found.lexically_normal().string();
}

EvalOptions evalOptions(const AnalysisOptions& options) {
    EvalOptions eval;
    eval.limits = options.limits;
    // The front end's stack holds at most this many nested calls: a larger setting, from the
    // command line or the client, means "as deep as it goes" (crtc refuses it instead).
    eval.limits.maxDepth = std::min(eval.limits.maxDepth, Limits::kMaxSupportedDepth);
    eval.includes = options.includes;
    eval.assetRoots = options.assetRoots;
    eval.access = options.access;
    return eval;
}

namespace {

/// Top-level names of an included file: globals it assigns or reads.
void collectMentions(Node* node, IncludedFile& out, int macroDepth) {
    auto mention = [&](std::string_view name, SourceRange range, Binding binding, bool write,
                       const Expr* value) {
        if (binding != Binding::Global) return;
        out.mentions.push_back({std::string(name), range, write, write ? value : nullptr});
    };
    switch (node->kind) {
    case NodeKind::Var: {
        auto* v = static_cast<VarExpr*>(node);
        mention(v->name, v->range, v->resolution.binding, false, nullptr);
        return;
    }
    case NodeKind::Assign: {
        auto* a = static_cast<AssignExpr*>(node);
        mention(a->name, a->nameRange, a->resolution.binding, macroDepth == 0, a->value);
        break;
    }
    case NodeKind::For: {
        auto* f = static_cast<ForStmt*>(node);
        mention(f->variable, f->variableRange, f->resolution.binding, macroDepth == 0, nullptr);
        break;
    }
    case NodeKind::Include: {
        out.includes.emplace_back(static_cast<IncludeStmt*>(node)->path->value);
        return;
    }
    default: break;
    }
    int depth = macroDepth + (node->kind == NodeKind::Macro ? 1 : 0);
    forEachChild(node, [&](Node* child) { collectMentions(child, out, depth); });
}

std::shared_ptr<const IncludedFile> parseIncluded(const std::string& path, std::string text) {
    auto included = std::make_shared<IncludedFile>();
    included->path = path;
    included->file = std::make_unique<SourceFile>(path, std::move(text));
    included->arena = std::make_unique<Arena>();
    runOnLargeStack([&] {
        DiagnosticBag ignored; // reported by the diagnostics of the including document
        included->script = parse(*included->file, 0, *included->arena, ignored);
        GlobalTable globals;
        resolve(included->script, globals, ignored, false);
        for (Node* item : included->script.items) collectMentions(item, *included, 0);
    });
    std::stable_sort(included->mentions.begin(), included->mentions.end(),
                     [](const auto& a, const auto& b) { return a.range.begin < b.range.begin; });
    std::set<std::string> defined;
    for (IncludedFile::Mention& m : included->mentions) {
        if (m.definition && !defined.insert(m.name).second) m.definition = false;
    }
    return included;
}

} // namespace

std::shared_ptr<const IncludedFile> IncludeCache::get(const std::string& path) {
    std::error_code error;
    auto mtime = fs::last_write_time(path, error);
    if (error) return nullptr;
    auto it = entries_.find(path);
    if (it != entries_.end() && it->second.mtime == mtime) return it->second.file;
    std::optional<std::string> text = readFile(path);
    if (!text || !isScriptText(*text)) return nullptr; // a binary file is not indexed
    auto parsed = parseIncluded(path, std::move(*text));
    entries_[path] = {mtime, parsed};
    return parsed;
}

// ---------------------------------------------------------------- the index

namespace {

class Indexer {
public:
    explicit Indexer(Analysis& analysis) : a_(analysis) {}

    void run() {
        for (Node* item : a_.compilation.main.items) visit(item);
        // The walk is mostly in source order already: sort only when it was not.
        auto byOccurrence = [](const Occurrence& x, const Occurrence& y) { return x.range.begin < y.range.begin; };
        if (!std::is_sorted(a_.occurrences.begin(), a_.occurrences.end(), byOccurrence)) {
            std::stable_sort(a_.occurrences.begin(), a_.occurrences.end(), byOccurrence);
        }
        auto byAttribute = [](const AttributeUse& x, const AttributeUse& y) { return x.nameRange.begin < y.nameRange.begin; };
        if (!std::is_sorted(a_.attributes.begin(), a_.attributes.end(), byAttribute)) {
            std::stable_sort(a_.attributes.begin(), a_.attributes.end(), byAttribute);
        }
        for (Occurrence& o : a_.occurrences) {
            Symbol& s = a_.symbols[o.symbol];
            if (o.write && !s.definition) {
                s.definition = o.range;
                o.definition = true;
                if (s.kind == SymbolKind::Variable && values_.count(o.range.begin)) {
                    s.value = values_[o.range.begin];
                    if (s.value && s.value->kind == NodeKind::Macro) s.kind = SymbolKind::Macro;
                }
                if (s.kind == SymbolKind::Variable && loopVariables_.count(o.range.begin)) {
                    s.kind = SymbolKind::LoopVariable;
                }
            }
        }
    }

    std::vector<std::string> includeNames; ///< of every include, in order
    /// Keyed by the AST's names, which point into the script and live as long as the analysis.
    std::unordered_map<std::string_view, uint32_t> globals;

private:
    uint32_t symbolFor(std::string_view name, const Resolution& r) {
        if (r.binding == Binding::Parameter && !functions_.empty()) {
            // A Function's parameters are its own, the first of a name listed twice too.
            const FunctionExpr* owner = functions_.back();
            uint32_t slot = r.slot;
            for (uint32_t i = 0; i < slot; ++i)
                if (owner->params[i].name == name) slot = i;
            auto key = std::make_pair(static_cast<const Expr*>(owner), slot);
            auto it = locals_.find(key);
            if (it != locals_.end()) return it->second;
            uint32_t id = add(name, SymbolKind::Parameter, owner);
            locals_.emplace(key, id);
            return id;
        }
        if (r.binding == Binding::Builtin) {
            auto it = builtins_.find(name);
            if (it != builtins_.end()) return it->second;
            uint32_t id = add(name, SymbolKind::Builtin, nullptr);
            builtins_.emplace(name, id);
            return id;
        }
        if ((r.binding == Binding::Local || r.binding == Binding::Enclosing) && r.depth < macros_.size()) {
            const MacroExpr* owner = macros_[macros_.size() - 1 - r.depth];
            auto key = std::make_pair(static_cast<const Expr*>(owner), r.slot);
            auto it = locals_.find(key);
            if (it != locals_.end()) return it->second;
            uint32_t id = add(name, SymbolKind::Variable, owner);
            locals_.emplace(key, id);
            return id;
        }
        auto it = globals.find(name);
        if (it != globals.end()) return it->second;
        uint32_t id = add(name, SymbolKind::Variable, nullptr);
        globals.emplace(name, id);
        return id;
    }

    uint32_t add(std::string_view name, SymbolKind kind, const Expr* scope) {
        Symbol s;
        s.name = std::string(name);
        s.kind = kind;
        s.scope = scope;
        a_.symbols.push_back(std::move(s));
        return static_cast<uint32_t>(a_.symbols.size() - 1);
    }

    void mention(std::string_view name, SourceRange range, const Resolution& r, bool write) {
        if (range.file != 0) return;
        // `x += 1` reads and writes x at one place: one occurrence, the write.
        if (!a_.occurrences.empty() && a_.occurrences.back().range == range) return;
        a_.occurrences.push_back({range, symbolFor(name, r), write, false});
    }

    void attributes(ObjectType type, std::span<Attribute> attrs) {
        for (Attribute& attr : attrs) {
            a_.attributes.push_back({attr.nameRange, type, type == ObjectType::Count ? -1 : attr.slot});
            visit(attr.value);
        }
    }

    void visit(Node* node) {
        switch (node->kind) {
        case NodeKind::Var: {
            auto* v = static_cast<VarExpr*>(node);
            mention(v->name, v->range, v->resolution, false);
            return;
        }
        case NodeKind::Assign: {
            auto* as = static_cast<AssignExpr*>(node);
            mention(as->name, as->nameRange, as->resolution, true);
            values_[as->nameRange.begin] = as->value;
            visit(as->value);
            return;
        }
        case NodeKind::For: {
            auto* f = static_cast<ForStmt*>(node);
            mention(f->variable, f->variableRange, f->resolution, true);
            loopVariables_.insert(f->variableRange.begin);
            visit(f->iterable);
            visit(f->body);
            return;
        }
        case NodeKind::Object: {
            auto* o = static_cast<ObjectExpr*>(node);
            attributes(o->type, o->attributes);
            return;
        }
        case NodeKind::Settings:
            attributes(ObjectType::Settings, static_cast<SettingsStmt*>(node)->attributes);
            return;
        case NodeKind::Macro: {
            auto* m = static_cast<MacroExpr*>(node);
            a_.scopes.push_back(m);
            macros_.push_back(m);
            std::vector<std::string_view> seen;
            for (const Param& p : m->params) {
                if (std::find(seen.begin(), seen.end(), p.name) != seen.end()) continue;
                Resolution r{Binding::Local, 0, static_cast<uint32_t>(seen.size())};
                seen.push_back(p.name);
                uint32_t id = symbolFor(p.name, r);
                a_.symbols[id].kind = SymbolKind::Parameter;
                a_.occurrences.push_back({p.range, id, true, false});
            }
            visit(m->body);
            macros_.pop_back();
            return;
        }
        case NodeKind::Function: {
            auto* f = static_cast<FunctionExpr*>(node);
            a_.scopes.push_back(f);
            functions_.push_back(f);
            for (uint32_t i = 0; i < f->params.size(); ++i) {
                uint32_t id = symbolFor(f->params[i].name, {Binding::Parameter, 0, i});
                a_.occurrences.push_back({f->params[i].range, id, true, false});
            }
            visit(f->body);
            functions_.pop_back();
            return;
        }
        case NodeKind::Include: includeNames.emplace_back(static_cast<IncludeStmt*>(node)->path->value); return;
        default: forEachChild(node, [&](Node* child) { visit(child); }); return;
        }
    }

    Analysis& a_;
    std::vector<const MacroExpr*> macros_;
    struct LocalKeyHash {
        size_t operator()(const std::pair<const Expr*, uint32_t>& key) const {
            return std::hash<const void*>()(key.first) ^ (static_cast<size_t>(key.second) * 0x9E3779B97F4A7C15ull);
        }
    };
    std::unordered_map<std::pair<const Expr*, uint32_t>, uint32_t, LocalKeyHash> locals_;
    std::vector<const FunctionExpr*> functions_; ///< the Functions whose body the walk is in
    std::unordered_map<std::string_view, uint32_t> builtins_;
    std::unordered_map<uint32_t, const Expr*> values_; ///< by the offset of an assigned name
    std::unordered_set<uint32_t> loopVariables_;
};

} // namespace

std::shared_ptr<const Analysis> analyze(const std::string& path, std::string text,
                                        const AnalysisOptions& options, IncludeCache& cache) {
    return analyze(compile(path, std::move(text), evalOptions(options), false), options, cache);
}

std::shared_ptr<Analysis> analyze(Compilation compilation, const AnalysisOptions& options,
                                  IncludeCache& cache) {
    auto result = std::make_shared<Analysis>();
    result->compilation = std::move(compilation);
    index(*result, result->file(), options, cache);
    return result;
}

void index(Analysis& a, const SourceFile& file, const AnalysisOptions& options, IncludeCache& cache) {
    // Of the compilation, only `file`, the main script's AST and `resolved` are read here (and
    // the AST written only when it has syntax errors, so nothing evaluates it).
    a.syntaxErrors = !a.compilation.resolved;
    const std::string& path = file.path();
    DiagnosticBag ignored;
    a.tokens = lexAll(file, 0, ignored, &a.comments);
    runOnLargeStack([&] {
        if (a.syntaxErrors) {
            // compile() stops at syntax errors; the editor still wants names resolved.
            GlobalTable globals;
            DiagnosticBag scratch;
            resolve(a.compilation.main, globals, scratch, true);
        }
        Indexer indexer(a);
        indexer.run();
        std::vector<std::string>& includeNames = indexer.includeNames;

        // Included files, breadth first, each once.
        std::error_code error;
        std::string folder = fs::absolute(path, error).parent_path().string();
        const FileAccess access =
            scriptFileAccess(folder, options.includes, options.assetRoots, options.access);
        std::vector<std::pair<std::string, std::string>> pending; // name, folder
        for (const std::string& name : includeNames) pending.emplace_back(name, folder);
        std::set<std::string> seen;
        for (size_t i = 0; i < pending.size() && i < 256; ++i) {
            std::string found = findInclude(pending[i].first, pending[i].second, options, access);
            if (found.empty()) continue;
            std::string canonical = fs::weakly_canonical(found, error).string();
            if (!seen.insert(canonical).second) continue;
            auto included = cache.get(found);
            if (!included) continue;
            a.includes.push_back(included);
            std::string innerFolder = fs::absolute(found, error).parent_path().string();
            for (const std::string& name : included->includes) pending.emplace_back(name, innerFolder);
        }
        std::set<std::string> externalNames;
        for (const auto& included : a.includes) {
            for (const IncludedFile::Mention& m : included->mentions) {
                if (!m.definition || !externalNames.insert(m.name).second) continue;
                a.externals.push_back({m.name, included, m.range, m.value});
                int index = static_cast<int>(a.externals.size() - 1);
                auto it = indexer.globals.find(m.name);
                if (it == indexer.globals.end()) {
                    Symbol s;
                    s.name = m.name;
                    s.value = m.value;
                    s.kind = m.value && m.value->kind == NodeKind::Macro ? SymbolKind::Macro
                                                                          : SymbolKind::Variable;
                    s.external = index;
                    a.symbols.push_back(std::move(s));
                } else if (!a.symbols[it->second].definition) {
                    Symbol& s = a.symbols[it->second];
                    s.external = index;
                    s.value = m.value;
                    if (m.value && m.value->kind == NodeKind::Macro) s.kind = SymbolKind::Macro;
                }
            }
        }
    });
}

std::shared_ptr<const Analysis> lexOnly(const std::string& path, std::string text) {
    auto result = std::make_shared<Analysis>();
    result->compilation.sources.add(path, std::move(text));
    result->syntaxErrors = true; // not parsed: nothing is known of its structure
    DiagnosticBag ignored;
    result->tokens = lexAll(result->file(), 0, ignored, &result->comments);
    return result;
}

// ---------------------------------------------------------------- queries

const Occurrence* Analysis::occurrenceAt(uint32_t offset) const {
    auto it = std::upper_bound(occurrences.begin(), occurrences.end(), offset,
                               [](uint32_t value, const Occurrence& o) { return value < o.range.begin; });
    if (it == occurrences.begin()) return nullptr;
    --it;
    return offset <= it->range.end ? &*it : nullptr;
}

const AttributeUse* Analysis::attributeAt(uint32_t offset) const {
    auto it = std::upper_bound(attributes.begin(), attributes.end(), offset,
                               [](uint32_t value, const AttributeUse& u) { return value < u.nameRange.begin; });
    if (it == attributes.begin()) return nullptr;
    --it;
    return offset <= it->nameRange.end ? &*it : nullptr;
}

int Analysis::tokenAt(uint32_t offset) const {
    auto it = std::upper_bound(tokens.begin(), tokens.end(), offset,
                               [](uint32_t value, const Token& t) { return value < t.begin; });
    if (it == tokens.begin()) return -1;
    --it;
    return offset <= it->end ? static_cast<int>(it - tokens.begin()) : -1;
}

int Analysis::tokenBefore(uint32_t offset) const {
    auto it = std::upper_bound(tokens.begin(), tokens.end(), offset,
                               [](uint32_t value, const Token& t) { return value < t.end; });
    return static_cast<int>(it - tokens.begin()) - 1;
}

std::vector<const Expr*> Analysis::scopesAt(uint32_t offset) const {
    std::vector<const Expr*> result;
    for (const Expr* scope : scopes) {
        // A macro's names are seen in its block; a Function's in its braces, whose first
        // and last bytes hold its body.
        const SourceRange inside = scope->kind == NodeKind::Macro
                                       ? static_cast<const MacroExpr*>(scope)->body->range
                                       : SourceRange{scope->range.file,
                                                     static_cast<const FunctionExpr*>(scope)->body->range.begin - 1,
                                                     scope->range.end};
        if (inside.begin < offset && offset < inside.end) result.push_back(scope);
    }
    return result;
}

ObjectType Analysis::enclosingObject(int index) const {
    int depth = 0;
    for (int i = index - 1; i >= 0; --i) {
        TokenKind k = tokens[static_cast<size_t>(i)].kind;
        if (k == TokenKind::RBrace) ++depth;
        if (k != TokenKind::LBrace || depth-- > 0) continue;
        if (i == 0) return ObjectType::Count;
        const Token& before = tokens[static_cast<size_t>(i - 1)];
        if (before.kind == TokenKind::KwSettings) return ObjectType::Settings;
        return before.kind == TokenKind::Name ? findObjectType(text(before)) : ObjectType::Count;
    }
    return ObjectType::Count;
}

const Symbol* Analysis::lookup(std::string_view name, uint32_t offset) const {
    std::vector<const Expr*> scopes = scopesAt(offset);
    for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
        for (const Symbol& s : symbols) {
            if (s.scope == *scope && s.name == name) return &s;
        }
    }
    for (const Symbol& s : symbols) {
        if (!s.scope && s.name == name && !s.builtin()) return &s;
    }
    for (const Symbol& s : symbols) {
        if (s.builtin() && s.name == name) return &s;
    }
    return nullptr;
}

// ---------------------------------------------------------------- static types

namespace {

/// "(a, b)": a macro's or Function's parameters as written.
std::string parameterList(std::span<const Param> params) {
    std::string text = "(";
    for (size_t i = 0; i < params.size(); ++i) {
        if (i) text += ", ";
        text += std::string(params[i].name);
    }
    return text + ")";
}

} // namespace

std::string staticType(const Expr* value, int depth) {
    if (!value || depth <= 0) return "";
    switch (value->kind) {
    case NodeKind::IntLit: return "int";
    case NodeKind::FloatLit: return "float";
    case NodeKind::StringLit: return "string";
    case NodeKind::BoolLit: return "bool";
    case NodeKind::List: return "list";
    case NodeKind::Object: {
        auto* o = static_cast<const ObjectExpr*>(value);
        return std::string(o->typeName);
    }
    case NodeKind::Macro: return "macro " + parameterList(static_cast<const MacroExpr*>(value)->params);
    case NodeKind::Function:
        return "Function " + parameterList(static_cast<const FunctionExpr*>(value)->params);
    case NodeKind::Modify: return staticType(static_cast<const ModifyExpr*>(value)->target, depth - 1);
    case NodeKind::ModifierList: return "modifiers";
    case NodeKind::Component: return "float";
    case NodeKind::Call: {
        auto* call = static_cast<const CallExpr*>(value);
        if (call->callee->kind != NodeKind::Var) return "";
        auto* callee = static_cast<const VarExpr*>(call->callee);
        if (callee->resolution.binding != Binding::Builtin) return "";
        std::string_view name = callee->name;
        if (name == "vec3" || name == "normalize" || name == "cross") return "vec3";
        if (name == "rgb" || name == "rgba") return "colour";
        if (name == "range") return "list";
        if (name == "str") return "string";
        if (name == "len" || name == "floor" || name == "ceil" || name == "round") return "int";
        return "";
    }
    case NodeKind::Binary: {
        auto* b = static_cast<const BinaryExpr*>(value);
        std::string left = staticType(b->left, depth - 1);
        std::string right = staticType(b->right, depth - 1);
        bool comparison = b->op >= BinaryOp::Less;
        if (comparison) return "bool";
        bool objects = (!left.empty() && std::isupper(static_cast<unsigned char>(left[0]))) ||
                       (!right.empty() && std::isupper(static_cast<unsigned char>(right[0])));
        if (objects) return "entity";
        if (left == right) return left;
        if ((left == "int" && right == "float") || (left == "float" && right == "int")) return "float";
        return "";
    }
    case NodeKind::Unary: {
        auto* u = static_cast<const UnaryExpr*>(value);
        return u->op == UnaryOp::Not ? "bool" : staticType(u->operand, depth - 1);
    }
    default: return "";
    }
}

} // namespace crt::lsp
