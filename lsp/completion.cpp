// Completion by context: the lexer's tokens around the cursor decide where we are (robust
// against syntax errors); the schema and the index say what fits there.
#include "completion.hpp"

#include "builtins.hpp"
#include "hover.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>

namespace crt::lsp {

using namespace lang;
namespace fs = std::filesystem;

std::string snippetToPlain(std::string_view s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size()) {
            out += s[++i];
        } else if (s[i] == '$' && i + 1 < s.size() && s[i + 1] == '{') {
            size_t colon = s.find(':', i);
            size_t close = s.find('}', i);
            if (colon != std::string_view::npos && colon < close) {
                out += s.substr(colon + 1, close - colon - 1);
            }
            i = close == std::string_view::npos ? s.size() : close;
        } else if (s[i] == '$' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]))) {
            ++i;
            while (i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]))) ++i;
        } else {
            out += s[i];
        }
    }
    return out;
}

namespace {

std::string_view placeholder(AttrType type) {
    switch (type) {
    case AttrType::Vec3: return "vec3(0, 0, 0)";
    case AttrType::Color: return "rgb(1, 1, 1)";
    case AttrType::Int: return "1";
    case AttrType::Float: return "1.0";
    case AttrType::Bool: return "true";
    case AttrType::String: return "\"\"";
    case AttrType::Material: return "Material { color -> rgb(1, 1, 1) }";
    case AttrType::LightList: return "[]";
    default: return "";
    }
}

std::string objectSnippet(const ObjectInfo& info) {
    std::string text = std::string(info.name) + " {";
    int n = 1;
    for (const AttributeInfo& attr : info.attributes) {
        if (!attr.required) continue;
        text += fmt::format(" {} -> ${{{}:{}}}", attr.name, n++, placeholder(attr.type));
    }
    if (n == 1) text += " $1"; // nothing required: the cursor goes inside the braces
    return text + " }$0";
}

bool isValueEnd(TokenKind k) {
    switch (k) {
    case TokenKind::Identifier: case TokenKind::Name: case TokenKind::Integer: case TokenKind::Float:
    case TokenKind::String: case TokenKind::KwTrue: case TokenKind::KwFalse: case TokenKind::RParen:
    case TokenKind::RBracket: case TokenKind::RBrace: case TokenKind::Greater:
        return true;
    default: return false;
    }
}

/// Which object types fit an attribute of type `type`.
bool objectFits(AttrType type, const ObjectInfo& info) {
    switch (type) {
    case AttrType::Material: return info.category == ObjectCategory::Material;
    case AttrType::Camera: return info.type == ObjectType::Camera;
    case AttrType::Background: return info.type == ObjectType::Background;
    case AttrType::Fog: return info.type == ObjectType::Fog;
    case AttrType::Medium: return info.type == ObjectType::Medium;
    case AttrType::FloatOrPattern: return isColorTexture(info.type) && info.type != ObjectType::Image;
    case AttrType::Texture: return isColorTexture(info.type);
    case AttrType::Bump: return isBumpTexture(info.type);
    case AttrType::Solid: return info.category == ObjectCategory::Entity && info.solid;
    case AttrType::Entity: return info.category == ObjectCategory::Entity && info.type != ObjectType::Mesh;
    case AttrType::BlobComponentList: return info.category == ObjectCategory::BlobComponent;
    case AttrType::Box: return info.type == ObjectType::Box;
    default: return false;
    }
}

/// Whether a variable of static type `type` ("" when unknown) may fit attribute type `want`.
int typeFit(AttrType want, const std::string& type) {
    if (type.empty() || type == "entity" || type.starts_with("macro")) return 1; // maybe
    ObjectType object = findObjectType(type);
    switch (want) {
    case AttrType::Float: return type == "float" || type == "int" ? 0 : -1;
    case AttrType::Int: return type == "int" ? 0 : -1;
    case AttrType::Bool: return type == "bool" ? 0 : -1;
    case AttrType::String: case AttrType::Choice: return type == "string" ? 0 : -1;
    case AttrType::Vec3: return type == "vec3" ? 0 : -1;
    case AttrType::Color: return type == "colour" ? 0 : -1;
    case AttrType::LightList: return type == "list" ? 0 : -1;
    case AttrType::Background:
        if (type == "colour") return 0;
        [[fallthrough]];
    case AttrType::FloatOrPattern:
        if (type == "float" || type == "int") return 0;
        [[fallthrough]];
    case AttrType::Material: case AttrType::Camera: case AttrType::Fog: case AttrType::Medium: case AttrType::Texture:
    case AttrType::Bump: case AttrType::Solid: case AttrType::Box: case AttrType::Entity:
        return object != ObjectType::Count && objectFits(want, objectInfo(object)) ? 0 : -1;
    case AttrType::Gamma: return type == "float" || type == "int" || type == "string" ? 0 : -1;
    case AttrType::Aperture: return type == "int" || type == "string" ? 0 : -1;
    case AttrType::ColorMap:
    case AttrType::MaterialMap:
    case AttrType::MaterialList:
    case AttrType::PatternList:
    case AttrType::SolidList:
    case AttrType::PointList:
    case AttrType::BlobComponentList:
    case AttrType::FaceList:
    case AttrType::FloatList: return type == "list" ? 0 : -1;
    case AttrType::Turbulence: return type == "float" || type == "int" || type == "vec3" ? 0 : -1;
    case AttrType::Function: return type.starts_with("Function") ? 0 : -1;
    }
    return 1;
}

class Completer {
public:
    Completer(const Analysis& a, uint32_t offset, const Analysis& names, uint32_t namesOffset,
              const AnalysisOptions& options)
        : a_(a), offset_(offset), names_(names), namesOffset_(namesOffset), options_(options) {}

    CompletionList run() {
        list_.replace = {0, offset_, offset_};
        for (const Token& c : a_.comments) {
            if (c.begin < offset_ && offset_ <= c.end) return list_; // nothing to offer in a comment
        }
        uint32_t wordStart = offset_;
        int at = a_.tokenAt(offset_);
        if (at >= 0) {
            const Token& t = token(at);
            if (t.begin < offset_ && (t.kind == TokenKind::Identifier || t.kind == TokenKind::Name || isKeyword(t.kind))) {
                wordStart = t.begin;
            } else if (insideString(t)) {
                stringContents(at);
                return list_;
            }
        }
        list_.replace = {0, wordStart, offset_};
        word(a_.tokenBefore(wordStart));
        return list_;
    }

private:
    /// The innermost '{' still open at a token, and whether a '(' or '[' opened after it is too.
    struct Enclosing {
        int brace = -1;
        bool inBrackets = false;
    };

    const Token& token(int index) const { return a_.tokens[static_cast<size_t>(index)]; }
    TokenKind kindOf(int index) const { return index >= 0 ? token(index).kind : TokenKind::EndOfFile; }

    /// Inside string token `at`: only an included file's name has completions.
    void stringContents(int at) {
        if (kindOf(at - 1) != TokenKind::KwInclude) return;
        list_.replace = {0, token(at).begin + 1, offset_}; // the name, not its opening quote
        includeFiles(false);
    }

    /// A word (maybe empty) after token `prev` (-1: at the start of the text); what fits is
    /// decided by that token and the blocks around it.
    void word(int prev) {
        TokenKind prevKind = kindOf(prev);
        if (prevKind == TokenKind::KwInclude) {
            includeFiles(true);
            return;
        }
        if (prevKind == TokenKind::Dot) {
            components(prev);
            return;
        }
        if (prevKind == TokenKind::ModifierOpen || prevKind == TokenKind::Less ||
            (prevKind == TokenKind::Comma && inModifierList(prev))) {
            modifiers();
            return;
        }
        Enclosing enclosing = enclosingBefore(prev);
        ObjectType object = objectOfBlock(enclosing.brace);
        if (object != ObjectType::Count && !enclosing.inBrackets) {
            objectBody(objectInfo(object), prev, enclosing.brace);
            return;
        }
        bool statementStart = prev < 0 || prevKind == TokenKind::LBrace || prevKind == TokenKind::RBrace ||
                              (isValueEnd(prevKind) && !enclosing.inBrackets);
        expressions(statementStart);
    }

    /// After `v.`: the components of a vec3, of a colour, or (type unknown) of both.
    void components(int dot) {
        std::string type;
        if (dot > 0 && kindOf(dot - 1) == TokenKind::Identifier) {
            const Symbol* s = names_.lookup(a_.text(token(dot - 1)), namesOffset_);
            if (s) type = staticType(s->value);
        }
        if (type != "colour")
            for (std::string_view c : {"x", "y", "z"})
                add({std::string(c), CompletionKind::Property, "vec3 component", "", std::string(c),
                     false, "0"});
        if (type != "vec3")
            for (std::string_view c : {"r", "g", "b", "a"})
                add({std::string(c), CompletionKind::Property, "colour component", "",
                     std::string(c), false, "1"});
    }

    void modifiers() {
        for (std::string_view m : {"translate", "rotate", "scale", "material", "matrix", "shadow", "camera", "reflected"}) {
            add({std::string(m), CompletionKind::Keyword, "modifier", "", std::string(m) + " ", false, "0"});
        }
    }

    /// Scans back from token `prev` (included) to the '{' that encloses it.
    Enclosing enclosingBefore(int prev) const {
        Enclosing enclosing;
        int depth = 0;
        int bracketDepth = 0;
        for (int i = prev; i >= 0; --i) {
            TokenKind k = token(i).kind;
            if (k == TokenKind::RBrace) ++depth;
            if (k == TokenKind::LBrace && depth-- == 0) {
                enclosing.brace = i;
                break;
            }
            if (depth == 0) {
                if (k == TokenKind::RParen || k == TokenKind::RBracket) ++bracketDepth;
                if (k == TokenKind::LParen || k == TokenKind::LParenLine || k == TokenKind::LBracket ||
                    k == TokenKind::LBracketLine) {
                    if (bracketDepth-- == 0) enclosing.inBrackets = true;
                    bracketDepth = std::max(bracketDepth, 0);
                }
            }
        }
        return enclosing;
    }

    /// The object (or Settings) whose block opens at token `brace`; Count for any other block.
    ObjectType objectOfBlock(int brace) const {
        if (brace <= 0) return ObjectType::Count;
        const Token& before = token(brace - 1);
        if (before.kind == TokenKind::Name) return findObjectType(a_.text(before));
        if (before.kind == TokenKind::KwSettings) return ObjectType::Settings;
        return ObjectType::Count;
    }

    /// In the block of object `info` opened at token `brace`: after `attribute ->`, the values
    /// that fit it; where an attribute may start, those not given yet; elsewhere, expressions.
    void objectBody(const ObjectInfo& info, int prev, int brace) {
        TokenKind prevKind = kindOf(prev);
        if (prevKind == TokenKind::Arrow && prev > 0) {
            int slot = findAttribute(info, a_.text(token(prev - 1)));
            if (slot >= 0) values(info.attributes[static_cast<size_t>(slot)]);
            else expressions(false);
            return;
        }
        if (prev == brace || isValueEnd(prevKind)) attributes(info, brace);
        else expressions(false);
    }

    void add(CompletionItem item) { list_.items.push_back(std::move(item)); }

    /// Whether the cursor is inside string token `t` (an unterminated one included).
    bool insideString(const Token& t) const {
        std::string_view text = a_.text(t);
        if ((t.kind != TokenKind::String && t.kind != TokenKind::Invalid) || !text.starts_with('"')) return false;
        bool closed = text.size() >= 2 && text.ends_with('"');
        return t.begin < offset_ && (offset_ < t.end || !closed);
    }

    bool inModifierList(int index) {
        int depth = 0;
        for (int i = index; i >= 0; --i) {
            TokenKind k = a_.tokens[static_cast<size_t>(i)].kind;
            if (k == TokenKind::RParen || k == TokenKind::RBracket) ++depth;
            if (k == TokenKind::LParen || k == TokenKind::LParenLine || k == TokenKind::LBracket || k == TokenKind::LBracketLine) {
                if (depth-- == 0) return false;
            }
            if (depth == 0 && k == TokenKind::ModifierOpen) return true;
            if (depth == 0 && (k == TokenKind::Greater || k == TokenKind::LBrace || k == TokenKind::RBrace)) return false;
        }
        return false;
    }

    void attributes(const ObjectInfo& info, int brace) {
        std::set<std::string_view> given;
        int depth = 0;
        for (size_t i = static_cast<size_t>(brace) + 1; i < a_.tokens.size(); ++i) {
            TokenKind k = a_.tokens[i].kind;
            if (k == TokenKind::LBrace) ++depth;
            if (k == TokenKind::RBrace && depth-- == 0) break;
            if (depth == 0 && k == TokenKind::Arrow && a_.tokens[i - 1].begin != list_.replace.begin) {
                given.insert(a_.text(a_.tokens[i - 1])); // the word being typed is not given yet
            }
        }
        for (const AttributeInfo& attr : info.attributes) {
            if (given.count(attr.name)) continue;
            std::string detail = std::string(attrTypeName(attr.type));
            if (attr.required) detail += " (required)";
            else if (!attr.defaultText.empty()) detail += fmt::format(" = {}", attr.defaultText);
            add({std::string(attr.name), CompletionKind::Property, detail, attributeDoc(info, attr),
                 std::string(attr.name) + " -> ", false, attr.required ? "0" : "1"});
        }
    }

    void values(const AttributeInfo& attr) {
        switch (attr.type) {
        case AttrType::Vec3:
            add({"vec3", CompletionKind::Function, "vec3(x, y, z)", "", "vec3(${1:0}, ${2:0}, ${3:0})", true, "0"});
            break;
        case AttrType::Color:
        case AttrType::Background:
            add({"rgb", CompletionKind::Function, "rgb(r, g, b)", "", "rgb(${1:1}, ${2:1}, ${3:1})", true, "0"});
            add({"rgba", CompletionKind::Function, "rgba(r, g, b, a)", "", "rgba(${1:1}, ${2:1}, ${3:1}, ${4:1})", true, "0"});
            break;
        case AttrType::Bool:
            add({"true", CompletionKind::Keyword, "bool", "", "true", false, "0"});
            add({"false", CompletionKind::Keyword, "bool", "", "false", false, "0"});
            break;
        case AttrType::Choice:
        case AttrType::Aperture:
        case AttrType::Gamma:
            for (std::string_view choice : attr.choices) {
                add({fmt::format("\"{}\"", choice), CompletionKind::Value, "choice", "",
                     fmt::format("\"{}\"", choice), false, "0"});
            }
            if (attr.type == AttrType::Gamma && attr.choices.empty()) {
                add({"\"srgb\"", CompletionKind::Value, "the sRGB curve", "", "\"srgb\"", false, "0"});
            }
            break;
        case AttrType::LightList:
            add({"[…]", CompletionKind::Snippet, "a list of lights", "", "[${1}]", true, "0"});
            break;
        case AttrType::ColorMap:
            add({"[[0, …], [1, …]]", CompletionKind::Snippet, "a colour map", "",
                 "[[0, rgb(${1:0}, ${2:0}, ${3:0})], [1, rgb(${4:1}, ${5:1}, ${6:1})]]", true, "0"});
            break;
        case AttrType::Turbulence:
            add({"vec3", CompletionKind::Function, "vec3(x, y, z)", "", "vec3(${1:0.5}, ${2:0.5}, ${3:0.5})",
                 true, "0"});
            break;
        case AttrType::MaterialMap:
            add({"[[0, …], [1, …]]", CompletionKind::Snippet, "a material map", "",
                 "[[0, Material { ${1} }], [1, Material { ${2} }]]", true, "0"});
            break;
        case AttrType::MaterialList:
            add({"[…, …]", CompletionKind::Snippet, "layers, bottom first", "",
                 "[Material { ${1} }, Material { ${2} }]", true, "0"});
            break;
        case AttrType::PatternList:
            add({"[…, …]", CompletionKind::Snippet, "layers, bottom first", "",
                 "[Gradient { ${1} }, Bozo { ${2} }]", true, "0"});
            break;
        default: break;
        }
        for (const ObjectInfo& info : allObjectTypes()) {
            if (objectFits(attr.type, info)) {
                add({std::string(info.name), CompletionKind::Type, "object", objectTypeDoc(info),
                     objectSnippet(info), true, "0"});
            }
        }
        for (const Symbol* s : visibleSymbols()) {
            if (s->builtin()) continue;
            int fit = typeFit(attr.type, staticType(s->value));
            if (s->kind == SymbolKind::Macro) fit = 1;
            if (fit < 0) continue;
            add(symbolItem(*s, fit == 0 ? "0" : "2"));
        }
        if (attr.type == AttrType::Float || attr.type == AttrType::Int || attr.type == AttrType::Vec3) {
            for (const BuiltinInfo& b : builtinFunctions()) add(builtinItem(b, "3"));
        }
    }

    std::vector<const Symbol*> visibleSymbols() {
        std::vector<const Symbol*> result;
        std::vector<const Expr*> scopes = names_.scopesAt(namesOffset_);
        std::set<std::string_view> names;
        for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
            for (const Symbol& s : names_.symbols) {
                if (s.scope == *scope && names.insert(s.name).second) result.push_back(&s);
            }
        }
        for (const Symbol& s : names_.symbols) {
            // A global read but bound nowhere is no name to offer: usually the word being typed.
            bool bound = s.definition || s.external >= 0;
            if (!s.scope && !s.builtin() && bound && names.insert(s.name).second) result.push_back(&s);
        }
        return result;
    }

    CompletionItem symbolItem(const Symbol& s, std::string sort) {
        std::string type = staticType(s.value);
        if (s.kind == SymbolKind::Macro && s.value && s.value->kind == NodeKind::Macro) {
            auto* m = static_cast<const MacroExpr*>(s.value);
            std::string snippet = s.name + "(";
            for (size_t i = 0; i < m->params.size(); ++i) {
                if (i) snippet += ", ";
                snippet += fmt::format("${{{}:{}}}", i + 1, m->params[i].name);
            }
            return {s.name, CompletionKind::Macro, type, "", snippet + ")", true, std::move(sort)};
        }
        return {s.name, CompletionKind::Variable, type, "", s.name, false, std::move(sort)};
    }

    CompletionItem builtinItem(const BuiltinInfo& b, std::string sort) {
        std::string snippet = std::string(b.name) + "(";
        if (b.maxArgs != 0) snippet += "${1}";
        return {std::string(b.name), CompletionKind::Function, std::string(b.signature), std::string(b.doc),
                snippet + ")", true, std::move(sort)};
    }

    void expressions(bool statementStart) {
        for (const Symbol* s : visibleSymbols()) add(symbolItem(*s, "1"));
        for (const BuiltinInfo& b : builtinFunctions()) add(builtinItem(b, "3"));
        add({"t", CompletionKind::Variable, "animation time", "", "t", false, "3"});
        add({"clock", CompletionKind::Variable, "animation progress 0..1", "", "clock", false, "3"});
        for (const ObjectInfo& info : allObjectTypes()) {
            if (info.type == ObjectType::Settings) continue;
            add({std::string(info.name), CompletionKind::Type, "object", objectTypeDoc(info),
                 objectSnippet(info), true, "2"});
        }
        add({"Macro", CompletionKind::Keyword, "Macro (params) { … }", "", "Macro (${1}) {\n\t$0\n}", true, "4"});
        add({"Function", CompletionKind::Keyword, "Function (x, y, z) { … }", "",
             "Function (${1:x, y, z}) { $0 }", true, "4"});
        add({"true", CompletionKind::Keyword, "bool", "", "true", false, "4"});
        add({"false", CompletionKind::Keyword, "bool", "", "false", false, "4"});
        if (!statementStart) return;
        add({"Settings", CompletionKind::Keyword, "Settings { … }", objectTypeDoc(objectInfo(ObjectType::Settings)),
             "Settings {\n\t$0\n}", true, "4"});
        add({"Scene", CompletionKind::Keyword, "Scene { … }", "", "Scene {\n\t$0\n}", true, "4"});
        add({"include", CompletionKind::Keyword, "include \"file.crt\"", "", "include \"${1}\"", true, "4"});
        add({"while", CompletionKind::Keyword, "while (condition) { … }", "", "while (${1:condition}) {\n\t$0\n}", true, "4"});
        add({"for", CompletionKind::Keyword, "for x in list { … }", "", "for ${1:i} in ${2:range(10)} {\n\t$0\n}", true, "4"});
        add({"if", CompletionKind::Keyword, "if (condition) { … }", "", "if (${1:condition}) {\n\t$0\n}", true, "4"});
    }

    void includeFiles(bool quote) {
        std::error_code error;
        std::string folder = fs::absolute(a_.file().path(), error).parent_path().string();
        std::set<std::string> seen;
        for (const fs::path& dir : options_.includes.folders(folder)) {
            for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
                if (!it->is_regular_file(error) || it->path().extension() != ".crt") continue;
                std::string name = it->path().filename().string();
                if (it->path() == fs::path(a_.file().path()) || !seen.insert(name).second) continue;
                add({name, CompletionKind::File, dir.string(), "", quote ? fmt::format("\"{}\"", name) : name, false, "0"});
                if (seen.size() > 500) return;
            }
        }
    }

    const Analysis& a_; ///< the tokens and text around the cursor
    uint32_t offset_;
    const Analysis& names_; ///< the names in scope: a_, or an older analysis with the same names
    uint32_t namesOffset_;  ///< offset_ in the text of names_
    const AnalysisOptions& options_;
    CompletionList list_;
};

} // namespace

CompletionList complete(const Analysis& analysis, uint32_t offset, const AnalysisOptions& options) {
    return Completer(analysis, offset, analysis, offset, options).run();
}

CompletionList complete(const Analysis& current, uint32_t offset, const Analysis& names, uint32_t namesOffset,
                        const AnalysisOptions& options) {
    return Completer(current, offset, names, namesOffset, options).run();
}

} // namespace crt::lsp
