// A line of text as glyph outlines, read from a TrueType or OpenType font with FreeType and
// laid out as POV-Ray's text object lays it out. Shared by the front end (which reports a
// font it cannot read) and the renderer.
#pragma once

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace crt::scene {

/// The font a Text uses when it names none: DejaVu Sans, from Debian's fonts-dejavu-core.
inline constexpr std::string_view kDefaultFontFile =
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// One glyph placed on the line, in ems, the baseline at y = 0: closed loops of cubic Bézier
/// segments, four points each, a loop ending where a segment ends on its first point (as
/// PrismShape's Bézier points, with y for z).
struct GlyphOutline {
    std::vector<glm::dvec2> points;
    glm::dvec2 lo{0.0}, hi{0.0}; ///< the extent of the points
};

struct TextOutline {
    std::vector<GlyphOutline> glyphs; ///< the glyphs with ink, left to right
    std::vector<char32_t> missing;    ///< characters the font has no glyph for, once each

    size_t byteSize() const;
};

/// Lays out `text` (UTF-8) on one line in the font whose file's bytes are `font`: the first
/// glyph's ink starts at x = 0, and each next glyph's origin is the last one's advanced by its
/// width times `spacing`, plus the font's kerning of the pair. Nothing, and a message in
/// `error`, for bytes FreeType cannot read as a font or text that is not UTF-8.
std::optional<TextOutline> layoutText(std::span<const unsigned char> font, std::string_view text,
                                      double spacing, std::string& error);
/// The same, with the font read from a file.
std::optional<TextOutline> layoutText(const std::string& fontFile, std::string_view text,
                                      double spacing, std::string& error);

} // namespace crt::scene
