// Procedural and image textures (spec §5, ext), evaluated in the entity's object space.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/mapping_axis.hpp"
#include "tracer/image.hpp"
#include "tracer/patterns/color_map.hpp"
#include "tracer/transform.hpp"

#include <memory>

namespace crt::tracer {

class Texture {
public:
    /// `image` is the decoded file of an Image or ImageBump texture (null otherwise).
    Texture(const scene::TextureDesc& desc, const Image* image);

    /// The colour and alpha at an object-space point with surface coordinates uv, where the
    /// surface's world-space unit normal is `normal`; spherical and cylindrical image mappings
    /// wrap around `axis`.
    Vec4 color(const Vec3& objectPoint, const Vec2& uv, const Vec3& normal, const MappingAxis& axis) const;
    /// Whether color() can give an alpha below 1 (a map's stop, an image's alpha channel).
    bool translucent() const;
    /// A bump texture's height at a point (its gradient perturbs the normal).
    double height(const Vec3& objectPoint, const Vec2& uv, const MappingAxis& axis) const;
    /// A pattern's value at an object-space point (through the texture's modifiers): what a
    /// Bump and a MaterialMap read of their pattern. A discrete pattern's is its entry's index.
    double value(const Vec3& objectPoint, const Vec3& normal) const;
    bool isDiscrete() const { return scene::isDiscretePattern(desc_.kind); }
    bool isBump() const { return scene::isBumpKind(desc_.kind); }
    double strength() const { return desc_.strength; }
    /// The object-space distance over which a bump's slope is read. A discrete pattern is
    /// flat but at its edges, which it bevels this wide (POV-Ray's default accuracy, 0.02 of
    /// the pattern's units); any other bump is differentiated over a step too small to see.
    double slopeStep() const { return slopeStep_; }
    /// Whether height() reads the surface's uv (an ImageBump mapped "uv"), not the point.
    bool heightFromUv() const {
        return desc_.kind == scene::TextureKind::ImageBump &&
               desc_.mapping == scene::TextureMapping::Uv;
    }

  private:
    /// Where an image is read at an object-space point.
    Vec2 imageCoordinates(const Vec3& objectPoint, const Vec2& uv, const MappingAxis& axis) const;

    scene::TextureDesc desc_;
    const Image* image_;
    Transform toTexture_; ///< object space to texture space (the inverse of its modifiers)
    ColorMap colors_;
    std::shared_ptr<const Texture> pattern_; ///< a Bump's pattern
    double slopeStep_ = 1e-4;
};

} // namespace crt::tracer
