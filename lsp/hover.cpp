// Hover text from the object schema, the built-in table, the index and the last evaluation.
#include "hover.hpp"

#include "builtins.hpp"

#include <fmt/format.h>

namespace crt::lsp {

using namespace lang;

std::string objectTypeDoc(const ObjectInfo& info) {
    std::string text = fmt::format("```crt\n{}\n```\n{}\n\n", info.name, info.doc);
    for (const AttributeInfo& attr : info.attributes) {
        text += fmt::format("- `{}`: {}{}\n", attr.name, attrTypeName(attr.type),
                            attr.required ? " (required)"
                                          : attr.defaultText.empty() ? std::string()
                                                                     : fmt::format(" = {}", attr.defaultText));
    }
    return text;
}

std::string attributeDoc(const ObjectInfo& owner, const AttributeInfo& attr) {
    std::string text = fmt::format("```crt\n{}.{}: {}\n```\n", owner.name, attr.name, attrTypeName(attr.type));
    if (attr.required) {
        text += "Required.";
    } else if (!attr.defaultText.empty()) {
        text += fmt::format("Default: `{}`.", attr.defaultText);
    }
    if (!attr.doc.empty()) text += fmt::format("\n\n{}", attr.doc);
    if (!attr.choices.empty()) {
        text += "\n\nOne of:";
        for (std::string_view choice : attr.choices) text += fmt::format(" `\"{}\"`", choice);
    }
    return text;
}

namespace {

std::string_view kindWord(SymbolKind kind) {
    switch (kind) {
    case SymbolKind::Parameter: return "parameter";
    case SymbolKind::LoopVariable: return "loop variable";
    case SymbolKind::Macro: return "macro";
    case SymbolKind::Builtin: return "built-in";
    default: return "variable";
    }
}

/// "Sphere { center -> vec3(0, 1, 0), radius -> 0.68 }", shortened: the literal as written.
std::string literalSummary(const Analysis& a, const Expr* value, const SourceFile& file) {
    std::string_view text = file.text().substr(value->range.begin, value->range.end - value->range.begin);
    std::string flat;
    bool space = false;
    for (char c : text) {
        if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
            space = !flat.empty();
            continue;
        }
        if (space) flat += ' ';
        space = false;
        flat += c;
        if (flat.size() > 160) return flat + " …";
    }
    (void)a;
    return flat;
}

/// A name nothing binds, in the script or the files it includes: said so, with the nearest
/// name that is bound.
std::string undefinedHover(const Analysis& a, const Symbol& undefined) {
    std::vector<std::string_view> bound;
    for (const Symbol& s : a.symbols)
        if (s.definition || s.external >= 0 || s.builtin()) bound.push_back(s.name);
    for (const BuiltinInfo& info : builtinFunctions()) bound.push_back(info.name);
    std::string text =
        fmt::format("```crt\n{}\n```\nUndefined: nothing in the script or the files it "
                    "includes assigns `{}`.",
                    undefined.name, undefined.name);
    if (std::string nearest = closestMatch(undefined.name, bound); !nearest.empty())
        text += fmt::format(" Did you mean `{}`?", nearest);
    return text;
}

std::string symbolHover(const Analysis& a, const Symbol& s, const GlobalValues* values) {
    if (s.builtin()) {
        for (const BuiltinInfo& info : builtinFunctions()) {
            if (info.name == s.name) return fmt::format("```crt\n{}\n```\n{}", info.signature, info.doc);
        }
        if (s.name == "t") return "```crt\nt\n```\nThe animation time: the frame number with `--frames N`, the float `T` with `--time T`, else 0.";
        if (s.name == "clock") return "```crt\nclock\n```\nThe animation's progress from 0.0 to 1.0 (`t / (N - 1)`).";
        return fmt::format("built-in `{}`", s.name);
    }
    if (!s.definition && s.external < 0) return undefinedHover(a, s);
    std::string type = staticType(s.value);
    std::string text = fmt::format("```crt\n({}) {}{}\n```", kindWord(s.kind), s.name,
                                   type.empty() ? std::string() : ": " + type);
    if (!s.scope && values) {
        for (const auto& [name, value] : *values) {
            if (name == s.name) {
                text += fmt::format("\nValue: `{}`", value);
                break;
            }
        }
    }
    if (s.value && (s.value->kind == NodeKind::Object || s.value->kind == NodeKind::Modify)) {
        const SourceFile& file = s.external >= 0 ? *a.externals[static_cast<size_t>(s.external)].file->file : a.file();
        text += fmt::format("\n\n`{}`", literalSummary(a, s.value, file));
    }
    if (s.external >= 0) {
        text += fmt::format("\n\nDefined in `{}`", a.externals[static_cast<size_t>(s.external)].file->path);
    }
    return text;
}

std::string_view keywordDoc(TokenKind kind) {
    switch (kind) {
    case TokenKind::KwSettings: return "`Settings { … }`: image size, camera, lights, background and quality. At most once.";
    case TokenKind::KwScene: return "`Scene { … }`: each statement whose value is an entity (or a list of them) draws it.";
    case TokenKind::KwMacro: return "`Macro (params) { … }`: a closure. A call yields the entities its body emits, or the value of its last statement.";
    case TokenKind::KwFunction: return "`Function (x, y, z) { expression }`: a numeric function, compiled when made: for Isosurface, HeightField and FunctionPattern, or called as f(1, 2, 3).";
    case TokenKind::KwScale: return "`scale s`: scales by a number or a vec3, about the origin.";
    case TokenKind::KwTranslate: return "`translate v`: moves by the vec3 v.";
    case TokenKind::KwRotate: return "`rotate vec3(x, y, z)`: rotates by x, then y, then z degrees about the world axes (left-handed).";
    case TokenKind::KwWhile: return "`while (condition) { … }`: repeats while the bool condition holds.";
    case TokenKind::KwFor: return "`for x in list { … }`: iterates a list or a `range(…)`.";
    case TokenKind::KwIf: return "`if (condition) { … } else { … }`";
    case TokenKind::KwInclude: return "`include \"file.crt\"`: runs another file in the global scope, once.";
    default: return "";
    }
}

/// `v.x`, `c.r`: what a component's name reads.
std::string_view componentDoc(std::string_view name) {
    if (name == "x") return "`v.x`: the x component of a vec3 (a float).";
    if (name == "y") return "`v.y`: the y component of a vec3 (a float).";
    if (name == "z") return "`v.z`: the z component of a vec3 (a float).";
    if (name == "r") return "`c.r`: the red component of a colour (a float).";
    if (name == "g") return "`c.g`: the green component of a colour (a float).";
    if (name == "b") return "`c.b`: the blue component of a colour (a float).";
    if (name == "a") return "`c.a`: the alpha of a colour (a float; 1 is opaque).";
    return "";
}

} // namespace

std::optional<Hover> hover(const Analysis& a, uint32_t offset, const GlobalValues* values) {
    int index = a.tokenAt(offset);
    if (index < 0) return std::nullopt;
    const Token& t = a.tokens[static_cast<size_t>(index)];
    SourceRange range{0, t.begin, t.end};
    if (t.kind == TokenKind::Name) {
        ObjectType type = findObjectType(a.text(t));
        if (type == ObjectType::Count) return std::nullopt;
        return Hover{range, objectTypeDoc(objectInfo(type))};
    }
    if (t.kind == TokenKind::KwSettings) return Hover{range, objectTypeDoc(objectInfo(ObjectType::Settings))};
    if (std::string_view doc = keywordDoc(t.kind); !doc.empty()) return Hover{range, std::string(doc)};
    if (t.kind != TokenKind::Identifier) return std::nullopt;
    if (const AttributeUse* use = a.attributeAt(offset); use && use->nameRange.begin == t.begin) {
        if (use->type == ObjectType::Count || use->slot < 0) return std::nullopt;
        const ObjectInfo& info = objectInfo(use->type);
        return Hover{range, attributeDoc(info, info.attributes[static_cast<size_t>(use->slot)])};
    }
    if (const Occurrence* o = a.occurrenceAt(offset); o && o->range.begin == t.begin) {
        return Hover{range, symbolHover(a, a.symbols[o->symbol], values)};
    }
    if (index > 0 && a.tokens[static_cast<size_t>(index) - 1].kind == TokenKind::Dot) {
        if (std::string_view doc = componentDoc(a.text(t)); !doc.empty())
            return Hover{range, std::string(doc)};
        return std::nullopt;
    }
    // An attribute the parser could not keep (a broken object): its object from the tokens.
    if (static_cast<size_t>(index) + 1 < a.tokens.size() && a.tokens[static_cast<size_t>(index) + 1].kind == TokenKind::Arrow) {
        ObjectType type = a.enclosingObject(index);
        if (type == ObjectType::Count) return std::nullopt;
        const ObjectInfo& info = objectInfo(type);
        int slot = findAttribute(info, a.text(t));
        if (slot < 0) return std::nullopt;
        return Hover{range, attributeDoc(info, info.attributes[static_cast<size_t>(slot)])};
    }
    // Where the parse failed there is no index: fall back on the name's scope.
    if (const Symbol* s = a.lookup(a.text(t), offset)) return Hover{range, symbolHover(a, *s, values)};
    return std::nullopt;
}

} // namespace crt::lsp
