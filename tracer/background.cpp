// Backgrounds; the panorama uses the corrected equirectangular mapping of spec §5.
#include "tracer/background.hpp"

#include "tracer/lights.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Background::Background(const scene::BackgroundDesc& desc, const Image* panorama)
    : kind_(desc.kind), color_(rgb(desc.color)), horizon_(rgb(desc.horizon)), sky_(rgb(desc.sky)),
      panorama_(panorama), angle_(desc.angle) {
    for (const scene::TextureDesc& layer : desc.layers) layers_.emplace_back(layer, nullptr);
}

Vec3 Background::radiance(const Vec3& d) const {
    switch (kind_) {
    case scene::BackgroundKind::Solid: return color_;
    case scene::BackgroundKind::Gradient: {
        double e = std::min(std::abs(d.y), 1.0);
        return horizon_ + (sky_ - horizon_) * e;
    }
    case scene::BackgroundKind::Image: {
        if (!panorama_ || panorama_->width == 0) return color_;
        const Vec2 uv = panoramaCoordinates(d);
        return panorama_->bilinear(uv.x, uv.y, false);
    }
    case scene::BackgroundKind::Pattern: return layered(d);
    }
    return color_;
}

Vec3 Background::layered(const Vec3& d) const {
    // From the top down: each layer adds its colour where its alpha covers what is left.
    Vec3 sum(0.0), uncovered(1.0);
    for (auto layer = layers_.rbegin(); layer != layers_.rend(); ++layer) {
        const Vec4 c = layer->color(d, Vec2(0.0), d, MappingAxis{});
        sum += Vec3(c) * c.a * uncovered;
        uncovered *= 1 - c.a;
    }
    return sum;
}

Vec2 Background::panoramaCoordinates(const Vec3& d) const {
    double a = std::fmod(angle_ + std::atan2(-d.x, d.z) + kPi, 2 * kPi);
    if (a < 0) a += 2 * kPi;
    double u = 1 - a / (2 * kPi);
    double v = 0.5 - std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi;
    return {u, v};
}

Vec3 Background::panoramaDirection(const Vec2& uv) const {
    // v runs from the zenith (0) to the nadir (1); u turns against the yaw `angle`.
    const double theta = uv.y * kPi, psi = 2 * kPi * (1 - uv.x) - kPi - angle_;
    const double r = std::sin(theta);
    return {-r * std::sin(psi), std::cos(theta), r * std::cos(psi)};
}

} // namespace crt::tracer
