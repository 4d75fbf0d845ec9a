// Compares two lexings of a document to decide whether the older analysis's names still hold.
#include "stale_names.hpp"

#include <algorithm>

namespace crt::lsp {

using namespace lang;

namespace {

bool isLiteral(TokenKind k) { return k == TokenKind::Integer || k == TokenKind::Float || k == TokenKind::String; }
bool isName(TokenKind k) { return k == TokenKind::Identifier || k == TokenKind::Name; }
bool isOpenParen(TokenKind k) { return k == TokenKind::LParen || k == TokenKind::LParenLine; }

/// Whether token `i` of `a` and `j` of `b` are the same token, maybe at another place: same
/// kind and text, the text of a literal aside (completion knows a value by its kind), unless
/// it names an included file (whose names are in scope).
bool sameToken(const Analysis& a, size_t i, const Analysis& b, size_t j) {
    const Token& x = a.tokens[i];
    const Token& y = b.tokens[j];
    if (x.kind != y.kind) return false;
    bool included = i > 0 && a.tokens[i - 1].kind == TokenKind::KwInclude;
    return (isLiteral(x.kind) && !included) || a.text(x) == b.text(y);
}

/// Whether the name at token `index` binds something or decides a value's type: changing it
/// may change the names in scope or what completion says of them.
bool bindsOrTypes(const Analysis& a, size_t index) {
    const std::vector<Token>& t = a.tokens;
    if (index + 1 < t.size()) {
        TokenKind next = t[index + 1].kind;
        if (next == TokenKind::Assign || next == TokenKind::LBrace || isOpenParen(next)) return true;
    }
    if (index > 0 && t[index - 1].kind == TokenKind::KwFor) return true;
    // A macro's or Function's parameter list: `Macro (a, b)`.
    for (size_t i = index; i-- > 0;) {
        TokenKind k = t[i].kind;
        if (k == TokenKind::Identifier || k == TokenKind::Comma) continue;
        return isOpenParen(k) && i > 0 &&
               (t[i - 1].kind == TokenKind::KwMacro || t[i - 1].kind == TokenKind::KwFunction);
    }
    return false;
}

} // namespace

std::optional<uint32_t> sameNamesAt(const Analysis& older, const Analysis& current, uint32_t offset) {
    std::string_view oldText = older.file().text();
    std::string_view newText = current.file().text();
    // The edits lie between a common prefix and a common suffix of the two texts.
    size_t shorter = std::min(oldText.size(), newText.size());
    size_t prefix = static_cast<size_t>(std::mismatch(oldText.begin(), oldText.begin() + static_cast<ptrdiff_t>(shorter),
                                                      newText.begin()).first -
                                        oldText.begin());
    size_t suffix = 0;
    while (suffix < shorter - prefix && oldText[oldText.size() - 1 - suffix] == newText[newText.size() - 1 - suffix]) {
        ++suffix;
    }
    const int64_t delta = static_cast<int64_t>(newText.size()) - static_cast<int64_t>(oldText.size());
    const size_t oldChangeEnd = oldText.size() - suffix;
    const size_t newChangeEnd = newText.size() - suffix;

    // Tokens of the common prefix and of the common suffix are the same in both lexings.
    const std::vector<Token>& a = older.tokens;
    const std::vector<Token>& b = current.tokens;
    size_t front = 0;
    while (front < a.size() && front < b.size() && a[front].kind == b[front].kind && a[front].begin == b[front].begin &&
           a[front].end == b[front].end && a[front].end < prefix) {
        ++front;
    }
    size_t back = 0;
    while (back < a.size() - front && back < b.size() - front) {
        const Token& x = a[a.size() - 1 - back];
        const Token& y = b[b.size() - 1 - back];
        if (x.kind != y.kind || x.begin < oldChangeEnd || y.begin != x.begin + delta || y.end != x.end + delta) break;
        ++back;
    }
    // Of the tokens between, pair those that are the same token, from both ends.
    size_t aEnd = a.size() - back, bEnd = b.size() - back;
    while (front < aEnd && front < bEnd && sameToken(older, front, current, front)) ++front;
    while (aEnd > front && bEnd > front && sameToken(older, aEnd - 1, current, bEnd - 1)) {
        --aEnd;
        --bEnd;
    }
    // What is left: at most one name on each side, neither binding nor typing anything.
    if (aEnd - front > 1 || bEnd - front > 1) return std::nullopt;
    if (aEnd > front && (!isName(a[front].kind) || bindsOrTypes(older, front))) return std::nullopt;
    if (bEnd > front && (!isName(b[front].kind) || bindsOrTypes(current, front))) return std::nullopt;

    // No brace changed, so every place of the edited stretch has the scopes of its start.
    if (offset <= prefix) return offset;
    if (offset >= newChangeEnd) return static_cast<uint32_t>(static_cast<int64_t>(offset) - delta);
    return static_cast<uint32_t>(std::min(prefix, oldChangeEnd));
}

} // namespace crt::lsp
