// Point, parallel, spot, area and cylinder lights.
#include "tracer/lights.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Light::Light(const scene::LightDesc& desc, int shadowSamples)
    : kind_(desc.kind), color_(rgb(desc.color)), ambient_(desc.ambient), falloff_(desc.falloff),
      attenuation_(desc.attenuation),
      attenuates_(desc.kind != scene::LightKind::Parallel && desc.attenuation != Vec3(1, 0, 0)) {
    switch (desc.kind) {
    case scene::LightKind::Point: position_ = desc.origin; break;
    case scene::LightKind::Parallel: direction_ = glm::normalize(desc.pointing - desc.from); break;
    case scene::LightKind::Spot: {
        position_ = desc.origin;
        direction_ = glm::normalize(desc.pointing - desc.origin);
        double half = std::clamp(desc.angle, 0.0, 360.0) * kPi / 360.0;
        double inner = half * (1 - std::clamp(desc.softness, 0.0, 1.0));
        cosOuter_ = std::cos(half);
        cosInner_ = std::cos(inner);
        break;
    }
    case scene::LightKind::Area: {
        position_ = desc.origin;
        edgeA_ = desc.edgeA;
        edgeB_ = desc.edgeB;
        sampleCount_ = std::max(shadowSamples, 1);
        // A near-square grid of strata, as many as there are samples.
        strataX_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(sampleCount_))));
        strataY_ = (sampleCount_ + strataX_ - 1) / strataX_;
        break;
    }
    case scene::LightKind::Cylinder:
        // A segment: as many strata along it as there are samples.
        position_ = desc.from;
        edgeA_ = desc.to - desc.from;
        sampleCount_ = std::max(shadowSamples, 1);
        strataX_ = sampleCount_;
        break;
    }
}

double Light::spotFactor(const Vec3& fromLight) const {
    double c = glm::dot(fromLight, direction_);
    if (c <= cosOuter_) return 0;
    if (c >= cosInner_) return 1;
    double x = (c - cosOuter_) / (cosInner_ - cosOuter_);
    return x * x * (3 - 2 * x); // smoothstep
}

LightSample Light::sample(const Vec3& point, int index, const Vec2& jitter) const {
    LightSample s;
    if (kind_ == scene::LightKind::Parallel) {
        s.toLight = -direction_;
        s.atInfinity = true;
        s.color = color_;
        return s;
    }
    Vec3 target = position_;
    Vec3 color = color_;
    if (kind_ == scene::LightKind::Area) {
        int sx = index % strataX_, sy = index / strataX_;
        double a = (sx + jitter.x) / strataX_, b = (sy + jitter.y) / strataY_;
        target = position_ + std::min(a, 1.0) * edgeA_ + std::min(b, 1.0) * edgeB_;
        color = color_ / static_cast<double>(sampleCount_);
    } else if (kind_ == scene::LightKind::Cylinder) {
        target = position_ + std::min((index + jitter.x) / sampleCount_, 1.0) * edgeA_;
        color = color_ / static_cast<double>(sampleCount_);
    }
    Vec3 offset = target - point;
    s.distance = glm::length(offset);
    s.toLight = s.distance > 0 ? offset / s.distance : Vec3(0, 1, 0);
    s.target = target;
    if (kind_ == scene::LightKind::Spot) color *= spotFactor(-s.toLight);
    s.color = color;
    return s;
}

} // namespace crt::tracer
