// Folding ranges: blocks, objects, lists and argument lists over several lines, comment runs.
#pragma once

#include "analysis.hpp"

#include <vector>

namespace crt::lsp {

struct FoldingRange {
    uint32_t startLine; ///< 0-based
    uint32_t endLine;
    bool comment = false;
};

std::vector<FoldingRange> foldingRanges(const Analysis& analysis);

} // namespace crt::lsp
