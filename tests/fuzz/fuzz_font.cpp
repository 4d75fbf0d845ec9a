// libFuzzer target for the font reader behind Text: arbitrary bytes as a TrueType or
// OpenType file, laid out with a line that has kerned pairs, holes, a space, an accent and a
// character DejaVu lacks.
#include "scene/curve_outline.hpp"
#include "scene/text_outline.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string error;
    std::optional<crt::scene::TextOutline> outline = crt::scene::layoutText(
        std::span<const unsigned char>(data, size), "AVTa 8B \xc3\xa9\xe4\xb8\xad", 1, error);
    if (!outline) {
        if (error.empty()) std::abort(); // a rejected font always says why
        return 0;
    }
    // The layout's promise, which the renderer's prisms rely on: finite points, four a
    // segment, every loop closed, the extent holding them.
    for (const crt::scene::GlyphOutline& g : outline->glyphs) {
        if (g.points.empty() || g.points.size() % 4 != 0) std::abort();
        for (const glm::dvec2& p : g.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) std::abort();
            if (p.x < g.lo.x || p.y < g.lo.y || p.x > g.hi.x || p.y > g.hi.y) std::abort();
        }
        if (crt::scene::curveLoops(g.points, crt::scene::SplineKind::Bezier).unclosedFrom >= 0)
            std::abort();
    }
    return 0;
}
