// Texture patterns. Checker, stripes, noise, marble and wood are solid (3D) textures.
#include "tracer/texture.hpp"

#include "tracer/lights.hpp"
#include "tracer/noise.hpp"

#include <cmath>

namespace crt::tracer {

namespace {

double fract(double x) { return x - std::floor(x); }
Vec3 mix(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

} // namespace

Texture::Texture(const scene::TextureDesc& desc, const Image* image)
    : desc_(desc), image_(image), toTexture_(Transform::fromModifiers(desc.modifiers).inverse()), a_(rgb(desc.a)),
      b_(rgb(desc.b)) {}

Vec2 Texture::imageCoordinates(const Vec3& p, const Vec2& uv) const {
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

Vec3 Texture::color(const Vec3& objectPoint, const Vec2& uv) const {
    Vec3 p = toTexture_.point(objectPoint);
    double s = desc_.size > 0 ? desc_.size : 1;
    switch (desc_.kind) {
    case scene::TextureKind::Checker: {
        // A tiny nudge keeps faces lying exactly on a cell boundary (z = 0 planes) on one color.
        Vec3 q = p / s + Vec3(1e-9);
        long sum = static_cast<long>(std::floor(q.x)) + static_cast<long>(std::floor(q.y)) +
                   static_cast<long>(std::floor(q.z));
        return (sum & 1) ? b_ : a_;
    }
    case scene::TextureKind::Stripes: {
        double along = glm::dot(p, glm::normalize(desc_.axis)) / s + 1e-9;
        return (static_cast<long>(std::floor(along)) & 1) ? b_ : a_;
    }
    case scene::TextureKind::Noise: return mix(a_, b_, fractalNoise(p / s, desc_.octaves));
    case scene::TextureKind::Marble: {
        double t = 0.5 + 0.5 * std::sin((p.x / s + desc_.turbulence * turbulence(p / s, desc_.octaves) * 4) * kPi);
        return mix(a_, b_, t);
    }
    case scene::TextureKind::Wood: {
        double r = std::sqrt(p.x * p.x + p.z * p.z) / s;
        double t = fract(desc_.rings * r + desc_.turbulence * 4 * (fractalNoise(p / s, 3) - 0.5));
        return mix(a_, b_, t < 0.5 ? 2 * t : 2 - 2 * t);
    }
    case scene::TextureKind::Image:
        if (!image_ || image_->width == 0) return a_;
        {
            Vec2 c = imageCoordinates(p, uv);
            return image_->bilinear(c.x, c.y, true);
        }
    case scene::TextureKind::NoiseBump:
    case scene::TextureKind::ImageBump: break;
    }
    return a_;
}

double Texture::height(const Vec3& objectPoint, const Vec2& uv) const {
    Vec3 p = toTexture_.point(objectPoint);
    double s = desc_.size > 0 ? desc_.size : 1;
    if (desc_.kind == scene::TextureKind::NoiseBump) return fractalNoise(p / s, desc_.octaves);
    if (desc_.kind == scene::TextureKind::ImageBump && image_ && image_->width > 0) {
        Vec2 c = imageCoordinates(p, uv);
        Vec3 v = image_->bilinear(c.x, c.y, true);
        return (v.x + v.y + v.z) / 3;
    }
    return 0;
}

} // namespace crt::tracer
