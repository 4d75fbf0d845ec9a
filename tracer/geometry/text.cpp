// The text primitive: POV-Ray's, glyph outlines on the x-y plane extruded along z.
#include "tracer/geometry/text.hpp"

#include <algorithm>
#include <limits>

namespace crt::tracer {

namespace {

/// The text's frame and a glyph prism's differ by swapping y and z (its own inverse).
Vec3 swapped(const Vec3& v) {
    return {v.x, v.z, v.y};
}

/// Whether the whole line meets the box (slabs; a line along a slab's faces counts as in).
/// The boxes are padded, which covers the rounding of the slab distances.
bool lineMeetsBox(const Ray& ray, const Bounds3& box) {
    double t0 = -std::numeric_limits<double>::infinity();
    double t1 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (ray.dir[k] == 0) {
            if (ray.origin[k] < box.lo[k] || ray.origin[k] > box.hi[k]) return false;
            continue;
        }
        double a = (box.lo[k] - ray.origin[k]) / ray.dir[k];
        double b = (box.hi[k] - ray.origin[k]) / ray.dir[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

} // namespace

TextGeometry::TextGeometry(const scene::TextShape& desc) {
    if (!desc.desc || !desc.desc->outline || !(desc.desc->thickness > 0)) return;
    auto glyphs = std::make_shared<std::vector<Glyph>>();
    const double thickness = desc.desc->thickness;
    uint32_t part = 0;
    for (const scene::GlyphOutline& g : desc.desc->outline->glyphs) {
        scene::PrismShape prism;
        prism.points = g.points;
        prism.to = thickness;
        prism.spline = scene::SplineKind::Bezier;
        const Bounds3 box = padded({Vec3(g.lo, 0), Vec3(g.hi, thickness)});
        glyphs->push_back({PrismGeometry(prism), box, part});
        part += static_cast<uint32_t>(2 + g.points.size() / 4); // end faces and walls
        bounds_ = unionOf(bounds_, box);
    }
    glyphs_ = std::move(glyphs);
}

void TextGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!glyphs_) return;
    const Ray inPrism{swapped(ray.origin), swapped(ray.dir)};
    CrossingList one;
    int glyphsMet = 0;
    for (const Glyph& g : *glyphs_) {
        if (!lineMeetsBox(ray, g.box)) continue;
        g.prism.crossLine(inPrism, one);
        for (int i = 0; i < one.count; ++i) out.add(one[i].t, g.firstPart + one[i].part);
        glyphsMet += one.count > 0;
    }
    if (glyphsMet > 1) out.sortByT();
}

SurfacePoint TextGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const std::vector<Glyph>& glyphs = *glyphs_;
    // The glyph whose parts hold this one: the last that starts at or before it.
    const auto after =
        std::upper_bound(glyphs.begin(), glyphs.end(), crossing.part,
                         [](uint32_t part, const Glyph& g) { return part < g.firstPart; });
    const Glyph& g = *(after - 1);
    const Ray inPrism{swapped(ray.origin), swapped(ray.dir)};
    SurfacePoint sp = g.prism.surfaceAt(inPrism, {crossing.t, crossing.part - g.firstPart}, wantUv);
    sp.point = swapped(sp.point);
    sp.pointError = swapped(sp.pointError);
    sp.normal = swapped(sp.normal);
    sp.shadingNormal = swapped(sp.shadingNormal);
    sp.dpdu = swapped(sp.dpdu);
    sp.dpdv = swapped(sp.dpdv);
    return sp;
}

} // namespace crt::tracer
