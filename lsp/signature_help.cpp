// Finds the open call around the cursor from the tokens (so unfinished calls work too).
#include "signature_help.hpp"

#include "builtins.hpp"

namespace crt::lsp {

using namespace lang;

namespace {

SignatureHelp fromLabel(std::string label, std::string doc) {
    SignatureHelp help{std::move(label), {}, std::move(doc), 0};
    size_t open = help.label.find('(');
    size_t close = help.label.rfind(')');
    if (open == std::string::npos || close == std::string::npos || close <= open + 1) return help;
    size_t start = open + 1;
    for (size_t i = start; i <= close; ++i) {
        if (i == close || help.label[i] == ',') {
            size_t b = start;
            while (b < i && help.label[b] == ' ') ++b;
            help.parameters.emplace_back(static_cast<uint32_t>(b), static_cast<uint32_t>(i));
            start = i + 1;
        }
    }
    return help;
}

} // namespace

std::optional<SignatureHelp> signatureHelp(const Analysis& a, uint32_t offset) {
    int depth = 0;
    uint32_t commas = 0;
    for (int i = a.tokenBefore(offset); i >= 0; --i) {
        const Token& t = a.tokens[static_cast<size_t>(i)];
        switch (t.kind) {
        case TokenKind::RParen: case TokenKind::RBracket: case TokenKind::RBrace: ++depth; break;
        case TokenKind::LBracket: case TokenKind::LBracketLine: case TokenKind::LParenLine: case TokenKind::LBrace:
            if (depth-- == 0) return std::nullopt; // inside a list, a block or a parenthesis
            break;
        case TokenKind::Comma:
            if (depth == 0) ++commas;
            break;
        case TokenKind::LParen: {
            if (depth-- > 0) break;
            if (i == 0 || a.tokens[static_cast<size_t>(i - 1)].kind != TokenKind::Identifier) return std::nullopt;
            const Token& callee = a.tokens[static_cast<size_t>(i - 1)];
            std::string_view name = a.text(callee);
            std::optional<SignatureHelp> help;
            const Symbol* s = a.lookup(name, callee.begin);
            if (s && !s->builtin() && s->value && s->value->kind == NodeKind::Macro) {
                auto* m = static_cast<const MacroExpr*>(s->value);
                std::string label = std::string(name) + "(";
                for (size_t p = 0; p < m->params.size(); ++p) {
                    if (p) label += ", ";
                    label += m->params[p].name;
                }
                help = fromLabel(label + ")", "macro");
            } else if (!s || s->builtin()) {
                for (const BuiltinInfo& b : builtinFunctions()) {
                    if (b.name == name) help = fromLabel(std::string(b.signature), std::string(b.doc));
                }
            }
            if (!help) return std::nullopt;
            help->activeParameter = help->parameters.empty()
                                        ? 0
                                        : std::min<uint32_t>(commas, static_cast<uint32_t>(help->parameters.size() - 1));
            return help;
        }
        default: break;
        }
    }
    return std::nullopt;
}

} // namespace crt::lsp
