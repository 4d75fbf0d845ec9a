// The code formatter: a script laid out in the one house style, its tokens unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace crt::lang {

struct FormatOptions {
    uint32_t indentWidth = 4;
    bool useTabs = false;
};

/// Replace bytes [begin, end) of the input with `replacement`.
struct FormatEdit {
    uint32_t begin;
    uint32_t end;
    std::string replacement;
};

struct FormatResult {
    bool ok = false;
    std::string error;             ///< why the text was left alone, when !ok
    std::string text;              ///< the formatted text, when ok (the whole file, range or not)
    std::vector<FormatEdit> edits; ///< one per changed line, in order, limited to the range if given
};

/// Formats a script: indentation by nesting (`indentWidth` per open bracket level), one space
/// around binary operators, `->` and `=`, after commas and inside braces, none inside
/// parentheses and brackets or after unary operators; trailing whitespace removed. Line
/// breaks, blank lines, comments and the spacing before trailing comments are kept as they
/// are: in CRT a line break can change what a bracket means (spec §1), so the formatter
/// never joins or splits lines. A script with syntax (or lexical) errors is refused: its
/// structure is not known well enough to indent it. Idempotent.
///
/// With `range` (byte offsets), only the lines it touches are changed in `edits`.
FormatResult formatSource(std::string_view source, const FormatOptions& options = {},
                          std::optional<std::pair<uint32_t, uint32_t>> range = std::nullopt);

} // namespace crt::lang
