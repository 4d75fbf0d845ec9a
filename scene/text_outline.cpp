// A line of text as glyph outlines, through FreeType (see text_outline.hpp).
#include "scene/text_outline.hpp"

#include "scene/utf8.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <fmt/format.h>
#include <glm/common.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>

namespace crt::scene {

namespace {

using V = glm::dvec2;

/// A glyph's contours in font units as they are decomposed, as Bézier points.
struct ContourBuilder {
    std::vector<V> points;
    V start{0.0}, current{0.0};
    size_t loopBegin = 0;

    void close() {
        if (points.size() > loopBegin && current != start) line(start);
        loopBegin = points.size();
    }
    void move(const V& p) {
        close();
        start = current = p;
    }
    void bezier(const V& c1, const V& c2, const V& to) {
        points.insert(points.end(), {current, c1, c2, to});
        current = to;
    }
    void line(const V& to) {
        if (to == current) return;
        bezier(current + (to - current) / 3.0, current + 2.0 * (to - current) / 3.0, to);
    }
    /// A quadratic arc as the cubic that traces it exactly.
    void conic(const V& c, const V& to) {
        bezier(current + 2.0 * (c - current) / 3.0, to + 2.0 * (c - to) / 3.0, to);
    }
};

V point(const FT_Vector* v) {
    return {static_cast<double>(v->x), static_cast<double>(v->y)};
}
ContourBuilder& builder(void* user) {
    return *static_cast<ContourBuilder*>(user);
}

const FT_Outline_Funcs kDecompose = {
    [](const FT_Vector* to, void* user) {
        builder(user).move(point(to));
        return 0;
    },
    [](const FT_Vector* to, void* user) {
        builder(user).line(point(to));
        return 0;
    },
    [](const FT_Vector* c, const FT_Vector* to, void* user) {
        builder(user).conic(point(c), point(to));
        return 0;
    },
    [](const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
        builder(user).bezier(point(c1), point(c2), point(to));
        return 0;
    },
    0,
    0,
};

std::string fontProblem(FT_Error error) {
    // Too short to hold a font's tables reads as a stream operation past the end.
    if (error == FT_Err_Unknown_File_Format || error == FT_Err_Invalid_Stream_Operation)
        return "not a TrueType or OpenType font";
    if (error == FT_Err_Cannot_Open_Resource) return "cannot open it";
    return fmt::format("the font is damaged (FreeType error {})", error);
}

struct FreeType {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~FreeType() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

/// Appends the glyph's outline with its origin at x = origin (font units), in ems; a glyph
/// without contours (a space) adds nothing.
FT_Error placeGlyph(FT_Outline& outline, double origin, double em,
                    std::vector<GlyphOutline>& glyphs) {
    ContourBuilder contours;
    if (FT_Error e = FT_Outline_Decompose(&outline, &kDecompose, &contours)) return e;
    contours.close();
    if (contours.points.empty()) return 0;
    GlyphOutline g;
    g.points.reserve(contours.points.size());
    for (const V& p : contours.points) g.points.push_back(V(origin + p.x, p.y) / em);
    g.lo = g.hi = g.points.front();
    for (const V& p : g.points) {
        g.lo = glm::min(g.lo, p);
        g.hi = glm::max(g.hi, p);
    }
    glyphs.push_back(std::move(g));
    return 0;
}

} // namespace

size_t TextOutline::byteSize() const {
    size_t bytes = sizeof(*this) + missing.size() * sizeof(char32_t);
    for (const GlyphOutline& g : glyphs) bytes += sizeof(g) + g.points.size() * sizeof(V);
    return bytes;
}

std::optional<TextOutline> layoutText(const std::string& fontFile, std::string_view text,
                                      double spacing, std::string& error) {
    std::ifstream in(fontFile, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        error = "cannot open it";
        return std::nullopt;
    }
    return layoutText(bytes, text, spacing, error);
}

std::optional<TextOutline> layoutText(std::span<const unsigned char> font, std::string_view text,
                                      double spacing, std::string& error) {
    FreeType ft;
    if (FT_Error e = FT_Init_FreeType(&ft.library)) {
        error = fontProblem(e);
        return std::nullopt;
    }
    if (FT_Error e = FT_New_Memory_Face(ft.library, font.data(), static_cast<FT_Long>(font.size()),
                                        0, &ft.face)) {
        error = fontProblem(e);
        return std::nullopt;
    }
    FT_Face face = ft.face;
    if (!FT_IS_SCALABLE(face) || face->units_per_EM == 0) {
        error = "the font has no outlines (a bitmap font)";
        return std::nullopt;
    }
    const double em = face->units_per_EM;
    TextOutline out;
    // POV-Ray's layout, in font units: the first glyph moved so that its ink starts at 0, and
    // each later one placed from the pen by its side bearing and the pair's kerning.
    double pen = 0;
    FT_UInt previous = 0;
    bool first = true;
    for (size_t at = 0; at < text.size();) {
        char32_t code = 0;
        const size_t length = decodeUtf8(text, at, code);
        if (length == 0) {
            error = fmt::format("the text is not UTF-8 at byte {}", at + 1);
            return std::nullopt;
        }
        at += length;
        const FT_UInt glyph = FT_Get_Char_Index(face, code);
        if (glyph == 0 &&
            std::find(out.missing.begin(), out.missing.end(), code) == out.missing.end())
            out.missing.push_back(code); // drawn as the font's missing-glyph shape, as POV-Ray
        if (FT_Error e = FT_Load_Glyph(face, glyph,
                                       FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) {
            error = fontProblem(e);
            return std::nullopt;
        }
        const FT_GlyphSlot slot = face->glyph;
        if (slot->format != FT_GLYPH_FORMAT_OUTLINE) {
            error = "the font has no outlines (a bitmap font)";
            return std::nullopt;
        }
        FT_BBox box;
        FT_Outline_Get_CBox(&slot->outline, &box);
        const double advance = static_cast<double>(slot->metrics.horiAdvance) * spacing;
        const double bearing = static_cast<double>(slot->metrics.horiBearingX);
        double origin;
        if (first) {
            first = false;
            origin = -static_cast<double>(box.xMin);
            pen = advance - bearing;
        } else {
            FT_Vector kern{0, 0};
            if (FT_HAS_KERNING(face))
                FT_Get_Kerning(face, previous, glyph, FT_KERNING_UNSCALED, &kern);
            origin = pen + bearing - static_cast<double>(box.xMin) + static_cast<double>(kern.x);
            pen += advance + static_cast<double>(kern.x);
        }
        previous = glyph;
        if (FT_Error e = placeGlyph(slot->outline, origin, em, out.glyphs)) {
            error = fontProblem(e);
            return std::nullopt;
        }
    }
    return out;
}

} // namespace crt::scene
