// Formatting over the lexer's tokens and comments; the AST tells unary operators and the
// '>' closing a modifier list apart from their binary look-alikes.
#include "formatter.hpp"

#include "large_stack.hpp"
#include "lexer.hpp"
#include "parser.hpp"

#include <algorithm>
#include <set>

namespace crt::lang {

namespace {

/// What the formatter needs of the syntax tree, by token position.
struct Shapes {
    std::set<uint32_t> unary;         ///< unary operators
    std::set<uint32_t> modifierClose; ///< the '>' closing a modifier list
    std::set<uint32_t> modifierWord;  ///< `material` and `matrix` in a modifier list
};

void collectShapes(Node* node, Shapes& shapes, const SourceFile& file) {
    if (node->kind == NodeKind::Unary)
        shapes.unary.insert(static_cast<UnaryExpr*>(node)->opRange.begin);
    std::span<Modifier> modifiers;
    if (node->kind == NodeKind::Modify) modifiers = static_cast<ModifyExpr*>(node)->modifiers;
    if (node->kind == NodeKind::ModifierList)
        modifiers = static_cast<ModifierListExpr*>(node)->modifiers;
    if (!modifiers.empty() && node->range.end > 0 && file.text()[node->range.end - 1] == '>') {
        shapes.modifierClose.insert(node->range.end - 1);
    }
    for (const Modifier& m : modifiers)
        if (namedModifier(opSpelling(m.op)))
            shapes.modifierWord.insert(m.range.begin);
    forEachChild(node, [&](Node* child) { collectShapes(child, shapes, file); });
}

bool isOpener(TokenKind k) {
    return k == TokenKind::LParen || k == TokenKind::LParenLine || k == TokenKind::LBracket ||
           k == TokenKind::LBracketLine || k == TokenKind::LBrace || k == TokenKind::ModifierOpen;
}

bool endsOperand(TokenKind k) {
    return k == TokenKind::Identifier || k == TokenKind::RParen || k == TokenKind::RBracket ||
           k == TokenKind::String;
}

bool isBinaryLike(TokenKind k) {
    switch (k) {
    case TokenKind::Plus: case TokenKind::Minus: case TokenKind::Star: case TokenKind::Slash:
    case TokenKind::Percent: case TokenKind::Caret: case TokenKind::Less: case TokenKind::Greater:
    case TokenKind::LessEqual: case TokenKind::GreaterEqual: case TokenKind::EqualEqual:
    case TokenKind::NotEqual: case TokenKind::AndAnd: case TokenKind::OrOr: case TokenKind::Question:
    case TokenKind::Colon:
    case TokenKind::Arrow:
    case TokenKind::Assign:
    case TokenKind::PlusAssign:
    case TokenKind::MinusAssign:
    case TokenKind::StarAssign:
    case TokenKind::SlashAssign: return true;
    default: return false;
    }
}

struct Item {
    Token token;
    bool unary = false;
    bool modifierClose = false;
    bool modifierWord = false; ///< `material` or `matrix` before its value: `<matrix [...]>`
};

/// The separator between two tokens on one line.
std::string_view spacing(const Item& prev, const Item& cur) {
    TokenKind p = prev.token.kind;
    TokenKind c = cur.token.kind;
    if (p == TokenKind::LParen || p == TokenKind::LParenLine || p == TokenKind::LBracket ||
        p == TokenKind::LBracketLine || p == TokenKind::ModifierOpen) {
        return "";
    }
    if (c == TokenKind::RParen || c == TokenKind::RBracket || c == TokenKind::Comma || cur.modifierClose) return "";
    if (p == TokenKind::Dot || c == TokenKind::Dot) return ""; // a component: `v.x`
    if ((c == TokenKind::LParen || c == TokenKind::LBracket) && endsOperand(p) &&
        !prev.modifierWord)
        return ""; // a call or an index
    if (prev.unary) return (c == TokenKind::Minus && p == TokenKind::Minus) ? " " : ""; // never "--"
    return " ";
}

/// Tokens and comments by line, in order, each marked if the AST says it is a unary
/// operator or the '>' closing a modifier list.
std::vector<std::vector<Item>> itemsByLine(const SourceFile& file, const Script& script,
                                          const std::vector<Token>& tokens,
                                          const std::vector<Token>& comments) {
    Shapes shapes;
    runOnLargeStack([&] { // expressions may nest tens of thousands deep
        for (Node* item : script.items) collectShapes(item, shapes, file);
    });
    std::vector<std::vector<Item>> lines(file.lineCount());
    auto addItem = [&](const Token& t) {
        uint32_t line = file.lineColumn(t.begin).line - 1;
        lines[line].push_back(
            {t, shapes.unary.count(t.begin) > 0,
             t.kind == TokenKind::Greater && shapes.modifierClose.count(t.begin) > 0,
             t.kind == TokenKind::Identifier && shapes.modifierWord.count(t.begin) > 0});
    };
    size_t c = 0;
    for (const Token& t : tokens) {
        for (; c < comments.size() && comments[c].begin < t.begin; ++c) addItem(comments[c]);
        addItem(t);
    }
    for (; c < comments.size(); ++c) addItem(comments[c]);
    return lines;
}

bool isCloser(const Item& item) {
    TokenKind k = item.token.kind;
    return k == TokenKind::RBrace || k == TokenKind::RParen || k == TokenKind::RBracket || item.modifierClose;
}

/// Formats line after line, keeping the brackets open so far.
class LineFormatter {
public:
    LineFormatter(const SourceFile& file, const FormatOptions& options)
        : file_(file),
          indentUnit_(options.useTabs ? std::string("\t") : std::string(options.indentWidth, ' ')) {}

    std::string format(const std::vector<Item>& items) {
        std::string formatted;
        if (items.empty()) return formatted;
        uint32_t level = indentLevel(items);
        for (uint32_t i = 0; i < level; ++i) formatted += indentUnit_;
        for (size_t i = 0; i < items.size(); ++i) {
            const Item& item = items[i];
            if (i > 0) {
                if (item.token.kind == TokenKind::Comment) {
                    // Trailing comments keep their distance: people align them.
                    uint32_t gap = item.token.begin - items[i - 1].token.end;
                    formatted += std::string(std::max<uint32_t>(gap, 1), ' ');
                } else {
                    formatted += spacing(items[i - 1], item);
                }
            }
            formatted += text(item);
            track(item, level);
        }
        return formatted;
    }

private:
    /// The nesting level of a line: one per open bracket, one less for a line that closes
    /// one, one more for a line continuing an expression (it starts with a binary operator,
    /// or the line before ended with one).
    uint32_t indentLevel(const std::vector<Item>& items) const {
        bool closer = isCloser(items.front());
        uint32_t level = open_.empty() ? 0 : closer ? open_.back().level : open_.back().level + 1;
        auto binary = [](const Item* item) {
            return item && !item->unary && !item->modifierClose && isBinaryLike(item->token.kind);
        };
        const Item* firstCode = nullptr;
        for (const Item& item : items) {
            if (item.token.kind != TokenKind::Comment) {
                firstCode = &item;
                break;
            }
        }
        if (firstCode && !closer && (binary(firstCode) || binary(lastCode_))) ++level;
        return level;
    }

    std::string_view text(const Item& item) const {
        std::string_view text = file_.text().substr(item.token.begin, item.token.end - item.token.begin);
        if (item.token.kind == TokenKind::Comment) {
            while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
                text.remove_suffix(1);
            }
        }
        return text;
    }

    void track(const Item& item, uint32_t level) {
        TokenKind kind = item.token.kind;
        if (kind != TokenKind::Comment) lastCode_ = &item;
        if (isOpener(kind)) {
            open_.push_back({kind, level});
        } else if (isCloser(item) && !open_.empty()) {
            open_.pop_back();
        }
    }

    struct Open {
        TokenKind kind;
        uint32_t level;
    };
    const SourceFile& file_;
    std::string indentUnit_;
    std::vector<Open> open_;
    const Item* lastCode_ = nullptr; ///< the last token (not comment) of the lines so far
};

/// Whether `out` lexes to exactly the tokens and comments of the original.
bool sameTokens(const std::string& out, const SourceFile& file, const std::vector<Token>& tokens,
                const std::vector<Token>& comments) {
    SourceFile check("<format>", out);
    DiagnosticBag checkDiagnostics;
    std::vector<Token> checkComments;
    std::vector<Token> after = lexAll(check, 0, checkDiagnostics, &checkComments);
    bool same = after.size() == tokens.size() && checkComments.size() == comments.size();
    for (size_t i = 0; same && i < after.size(); ++i) {
        same = after[i].kind == tokens[i].kind &&
               check.text().substr(after[i].begin, after[i].end - after[i].begin) ==
                   file.text().substr(tokens[i].begin, tokens[i].end - tokens[i].begin);
    }
    return same;
}

} // namespace

FormatResult formatSource(std::string_view source, const FormatOptions& options,
                          std::optional<std::pair<uint32_t, uint32_t>> range) {
    FormatResult result;
    SourceFile file("<format>", std::string(source));
    DiagnosticBag diagnostics;
    Arena arena;
    std::vector<Token> comments;
    Script script;
    // On the large stack, so that the nesting limit is the one compiling the script has.
    runOnLargeStack([&] { script = parse(file, 0, arena, diagnostics, &comments); });
    if (diagnostics.hasErrors()) {
        result.error = "the script has syntax errors; formatting needs a script that parses";
        return result;
    }
    DiagnosticBag ignored;
    std::vector<Token> tokens = lexAll(file, 0, ignored);
    std::vector<std::vector<Item>> lines = itemsByLine(file, script, tokens, comments);

    LineFormatter formatter(file, options);
    std::string out;
    out.reserve(source.size() + source.size() / 8);
    out += file.text().substr(0, file.lineStart(1)); // a byte-order mark stays
    for (uint32_t line = 0; line < file.lineCount(); ++line) {
        uint32_t start = file.lineStart(line + 1);
        std::string_view original = file.lineText(line + 1);
        std::string formatted = formatter.format(lines[line]);
        // The line break as it was (LF or CR LF), none after a last line that had none.
        uint32_t next = line + 1 < file.lineCount() ? file.lineStart(line + 2) : file.size();
        std::string_view lineBreak = file.text().substr(start + original.size(), next - start - original.size());
        out += formatted;
        out += lineBreak;
        bool inRange = !range || (start <= range->second && start + original.size() >= range->first);
        if (formatted != original && inRange) {
            result.edits.push_back({start, start + static_cast<uint32_t>(original.size()), formatted});
        }
    }
    // The tokens must be exactly the same, in the same order: otherwise refuse.
    if (!sameTokens(out, file, tokens, comments)) {
        result.edits.clear();
        result.error = "internal error: formatting would change the script's tokens";
        return result;
    }
    result.ok = true;
    result.text = std::move(out);
    return result;
}

} // namespace crt::lang
