// Textures: a pattern read through its colour map, or an image mapped onto the surface.
#include "tracer/texture.hpp"

#include "tracer/lights.hpp"
#include "tracer/noise.hpp"
#include "tracer/patterns/pattern.hpp"

#include <cmath>

namespace crt::tracer {

Texture::Texture(const scene::TextureDesc& desc, const Image* image)
    : desc_(desc), image_(image), toTexture_(Transform::fromModifiers(desc.modifiers).inverse()),
      colors_(desc.colors) {
    if (desc.kind == scene::TextureKind::Bump && !desc.pattern.empty()) {
        pattern_ = std::make_shared<const Texture>(desc.pattern.front(), nullptr);
        if (pattern_->isDiscrete()) {
            constexpr double kBevel = 0.02;
            glm::dmat3 toPattern = pattern_->toTexture_.linear() * toTexture_.linear();
            double step = kBevel / std::cbrt(std::abs(glm::determinant(toPattern)));
            if (std::isfinite(step)) slopeStep_ = step;
        }
    }
}

double Texture::value(const Vec3& objectPoint, const Vec3& normal) const {
    return patternValue(desc_, toTexture_.point(objectPoint), normal);
}

Vec2 Texture::imageCoordinates(const Vec3& objectPoint, const Vec2& uv, const MappingAxis& axis) const {
    // Spherical and cylindrical mappings wrap around the shape's own centre and axis (a
    // sphere made away from the origin is covered as one made there and moved); the texture's
    // modifiers then move the image about that centre.
    bool aroundShape = desc_.mapping == scene::TextureMapping::Spherical ||
                       desc_.mapping == scene::TextureMapping::Cylindrical;
    Vec3 p = toTexture_.point(aroundShape ? axis.toAxisSpace(objectPoint) : objectPoint);
    switch (desc_.mapping) {
    case scene::TextureMapping::Uv: return {uv.x, 1 - uv.y};
    case scene::TextureMapping::Planar: return {fract(p.x / desc_.size), fract(-p.y / desc_.size)};
    case scene::TextureMapping::Spherical: {
        double len = glm::length(p);
        if (len == 0) return {0, 0};
        Vec3 d = p / len;
        return {0.5 + std::atan2(d.x, d.z) / (2 * kPi), 0.5 - std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi};
    }
    case scene::TextureMapping::Cylindrical:
        return {0.5 + std::atan2(p.x, p.z) / (2 * kPi), fract(-p.y / desc_.size)};
    case scene::TextureMapping::Cubic: {
        Vec3 a = absolute(p);
        if (a.x >= a.y && a.x >= a.z) return {fract(p.z / desc_.size), fract(-p.y / desc_.size)};
        if (a.y >= a.z) return {fract(p.x / desc_.size), fract(p.z / desc_.size)};
        return {fract(p.x / desc_.size), fract(-p.y / desc_.size)};
    }
    }
    return uv;
}

Vec4 Texture::color(const Vec3& objectPoint, const Vec2& uv, const Vec3& normal,
                    const MappingAxis& axis) const {
    switch (desc_.kind) {
    case scene::TextureKind::Image:
        if (!image_ || image_->width == 0) return colors_.entry(0);
        {
            Vec2 c = imageCoordinates(objectPoint, uv, axis);
            return {image_->bilinear(c.x, c.y, true), image_->bilinearAlpha(c.x, c.y, true)};
        }
    case scene::TextureKind::NoiseBump:
    case scene::TextureKind::ImageBump:
    case scene::TextureKind::Bump: return colors_.entry(0);
    default: break;
    }
    double value = patternValue(desc_, toTexture_.point(objectPoint), normal);
    if (scene::isDiscretePattern(desc_.kind)) return colors_.entry(static_cast<size_t>(value));
    return colors_.at(value);
}

bool Texture::translucent() const {
    if (isBump()) return false;
    if (desc_.kind == scene::TextureKind::Image && image_ && image_->width > 0) {
        return !image_->alpha.empty();
    }
    return colors_.translucent();
}

double Texture::height(const Vec3& objectPoint, const Vec2& uv, const MappingAxis& axis) const {
    Vec3 p = toTexture_.point(objectPoint);
    double s = desc_.size > 0 ? desc_.size : 1;
    if (desc_.kind == scene::TextureKind::NoiseBump) return fractalNoise(p / s, desc_.octaves);
    if (desc_.kind == scene::TextureKind::Bump && pattern_) {
        double value = pattern_->value(p, Vec3(0, 1, 0));
        if (!pattern_->isDiscrete()) return value;
        return value / static_cast<double>(scene::discreteColorCount(pattern_->desc_.kind) - 1);
    }
    if (desc_.kind == scene::TextureKind::ImageBump && image_ && image_->width > 0) {
        Vec2 c = imageCoordinates(objectPoint, uv, axis);
        Vec3 v = image_->bilinear(c.x, c.y, true);
        return (v.x + v.y + v.z) / 3;
    }
    return 0;
}

} // namespace crt::tracer
