// Folds matched brackets from the tokens, so it works on broken files too.
#include "folding.hpp"

#include <algorithm>

namespace crt::lsp {

using namespace lang;

std::vector<FoldingRange> foldingRanges(const Analysis& a) {
    std::vector<FoldingRange> result;
    const SourceFile& file = a.file();
    auto line = [&](uint32_t offset) { return file.lineColumn(offset).line - 1; };
    std::vector<const Token*> open;
    for (const Token& t : a.tokens) {
        switch (t.kind) {
        case TokenKind::LBrace: case TokenKind::LBracket: case TokenKind::LBracketLine:
        case TokenKind::LParen: case TokenKind::LParenLine:
            open.push_back(&t);
            break;
        case TokenKind::RBrace: case TokenKind::RBracket: case TokenKind::RParen: {
            if (open.empty()) break;
            const Token* start = open.back();
            open.pop_back();
            uint32_t first = line(start->begin);
            uint32_t last = line(t.begin);
            // The closing line stays visible, as in most editors.
            if (last >= first + 2) result.push_back({first, last - 1, false});
            break;
        }
        default: break;
        }
    }
    result.erase(std::remove_if(result.begin(), result.end(), [](const FoldingRange& r) { return r.endLine <= r.startLine; }),
                 result.end());
    // Runs of two or more whole-line comments.
    uint32_t runStart = 0, runEnd = 0;
    bool inRun = false;
    for (const Token& c : a.comments) {
        uint32_t l = line(c.begin);
        bool wholeLine = file.lineStart(l + 1) + (file.lineText(l + 1).find_first_not_of(" \t")) == c.begin;
        if (!wholeLine) continue;
        if (inRun && l == runEnd + 1) {
            runEnd = l;
            continue;
        }
        if (inRun && runEnd > runStart) result.push_back({runStart, runEnd, true});
        inRun = true;
        runStart = runEnd = l;
    }
    if (inRun && runEnd > runStart) result.push_back({runStart, runEnd, true});
    std::sort(result.begin(), result.end(), [](const FoldingRange& x, const FoldingRange& y) {
        return x.startLine != y.startLine ? x.startLine < y.startLine : x.endLine > y.endLine;
    });
    return result;
}

} // namespace crt::lsp
