// The text primitive: POV-Ray's, glyph outlines on the x-y plane extruded along z.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/mapping_axis.hpp"
#include "tracer/geometry/prism.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// A line of glyphs (scene::TextOutline), each a prism of its outline from z = 0 to the
/// thickness: a solid, the union of the glyphs, which a font's glyphs do not overlap. UV on
/// each glyph as its prism's, with the prism's y (the height) along z.
class TextGeometry {
  public:
    /// Text without ink (spaces, or an outline not read) gives no crossings at all.
    explicit TextGeometry(const scene::TextShape& desc);

    Bounds3 bounds() const { return bounds_; }
    /// Every crossing with every glyph the line passes, ascending.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return true; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 0, 1)}; }

  private:
    /// A glyph's prism lies in its own frame, its y being the text's z: the two swap.
    struct Glyph {
        PrismGeometry prism;
        Bounds3 box;        ///< in the text's frame
        uint32_t firstPart; ///< the text's part numbers of this glyph start here
    };

    std::shared_ptr<const std::vector<Glyph>> glyphs_;
    Bounds3 bounds_;
};

} // namespace crt::tracer
