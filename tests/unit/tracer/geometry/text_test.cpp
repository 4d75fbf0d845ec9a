// Text: the layout FreeType gives (kerning, spacing, the first glyph's ink at x = 0), fonts
// that cannot be read, and crossings against the exact solid of straight-edged glyphs.
#include "geometry_test_support.hpp"

#include "tracer/geometry/text.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

const std::string kFont(scene::kDefaultFontFile);

scene::TextOutline layout(std::string_view text, double spacing = 1) {
    std::string error;
    std::optional<scene::TextOutline> outline = scene::layoutText(kFont, text, spacing, error);
    INFO(error);
    REQUIRE(outline);
    return *outline;
}

scene::TextShape shapeOf(std::string_view text, double thickness) {
    auto desc = std::make_shared<scene::TextDesc>();
    desc->text = text;
    desc->thickness = thickness;
    desc->outline = std::make_shared<const scene::TextOutline>(layout(text));
    return {desc};
}

/// Even-odd inside of the glyphs, their segments being straight (a Bézier segment of four
/// points on a line), between z = 0 and the thickness.
struct ExactStraightText {
    std::vector<std::pair<LD, LD>> a, b; ///< each edge's ends
    LD thickness;

    ExactStraightText(const scene::TextOutline& outline, double thick) : thickness(thick) {
        for (const scene::GlyphOutline& g : outline.glyphs)
            for (size_t i = 0; i + 3 < g.points.size(); i += 4) {
                a.push_back({g.points[i].x, g.points[i].y});
                b.push_back({g.points[i + 3].x, g.points[i + 3].y});
            }
    }
    bool inside(const LVec& q) const {
        if (q.z < 0 || q.z > thickness) return false;
        bool in = false;
        for (size_t i = 0; i < a.size(); ++i) {
            const auto [x0, y0] = a[i];
            const auto [x1, y1] = b[i];
            if ((y0 > q.y) != (y1 > q.y) && q.x < x0 + (q.y - y0) * (x1 - x0) / (y1 - y0)) in = !in;
        }
        return in;
    }
};

} // namespace

TEST_CASE("text: the first glyph's ink starts at 0, and the font's kerning is applied") {
    const scene::TextOutline hi = layout("HI");
    REQUIRE(hi.glyphs.size() == 2);
    CHECK(hi.glyphs[0].lo.x == 0);
    CHECK(hi.glyphs[0].lo.y == 0);
    CHECK(hi.glyphs[0].hi.y == Approx(0.729).margin(1e-3)); // DejaVu's cap height, in ems
    CHECK(hi.glyphs[0].points.size() % 4 == 0);
    // DejaVu Sans kerns A and V closer than A and A.
    const scene::TextOutline av = layout("AV"), aa = layout("AA");
    CHECK(av.glyphs[1].lo.x < aa.glyphs[1].lo.x - 0.05);
    // Spacing scales the advance: a space and a wider step.
    CHECK(layout("H H").glyphs.size() == 2);
    CHECK(layout("HI", 2).glyphs[1].lo.x > hi.glyphs[1].lo.x + 0.5);
    CHECK(layout("a\xe4\xb8\xad").missing == std::vector<char32_t>{0x4E2D});
}

TEST_CASE("text: a file that is not a font, or is absent, is an error that says so") {
    const auto path = std::filesystem::temp_directory_path() / "crt_text_test_not_a_font.ttf";
    std::ofstream(path) << "not a font";
    std::string error;
    CHECK_FALSE(scene::layoutText(path.string(), "crt", 1, error));
    CHECK(error == "not a TrueType or OpenType font");
    std::filesystem::remove(path);
    CHECK_FALSE(scene::layoutText("/nonexistent/font.ttf", "crt", 1, error));
    CHECK(error == "cannot open it");
    CHECK_FALSE(scene::layoutText(kFont, "\xff", 1, error));
    CHECK(error == "the text is not UTF-8 at byte 1");
}

TEST_CASE("text: random lines against the exact solid of straight glyphs") {
    const scene::TextShape shape = shapeOf("HIT", 0.3);
    const TextGeometry g(shape);
    const ExactStraightText exact(*shape.desc->outline, 0.3);
    const Bounds3 b = g.bounds();
    CHECK(b.lo.z <= 0);
    CHECK(b.hi.z >= 0.3);
    Random rng(91);
    int most = 0;
    for (int i = 0; i < 600; ++i) {
        const Vec3 target = rng.pointIn(b);
        const Ray ray = rng.lineThrough(target, 4);
        CrossingList list;
        g.crossLine(ray, list);
        checkAlternates(
            list, ray, [&](const LVec& q) { return exact.inside(q); }, true);
        most = std::max(most, list.count);
        for (int k = 0; k < list.count; ++k) {
            const SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            const LVec q(sp.point);
            const LD step = 1e-7L;
            CHECK(exact.inside(q - step * LVec(sp.normal)));
            CHECK_FALSE(exact.inside(q + step * LVec(sp.normal)));
        }
    }
    CHECK(most >= 4); // through two glyphs
    // Straight on from the front: in through the face at z = 0, out at the thickness.
    const Ray front{{0.8, 0.3, -2}, {0, 0, 1}};
    CrossingList list;
    g.crossLine(front, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2));
    CHECK(list[1].t == Approx(2.3));
    CHECK(g.surfaceAt(front, list[0]).normal.z == Approx(-1));
    CHECK(g.surfaceAt(front, list[1]).normal.z == Approx(1));
}

TEST_CASE("text: without ink, or without an outline, there is nothing to cross") {
    CrossingList list;
    TextGeometry(shapeOf("   ", 0.25)).crossLine({{0, 0, -1}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
    TextGeometry(scene::TextShape{std::make_shared<scene::TextDesc>()})
        .crossLine({{0, 0, -1}, {0, 0, 1}}, list);
    CHECK(list.count == 0);
}
