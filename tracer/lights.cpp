// Point, parallel, spot, area and cylinder lights.
#include "tracer/lights.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Light::Light(const scene::LightDesc& desc, int shadowSamples)
    : kind_(desc.kind), color_(rgb(desc.color)), ambient_(desc.ambient), falloff_(desc.falloff),
      attenuation_(desc.attenuation),
      attenuates_(desc.kind != scene::LightKind::Parallel && desc.attenuation != Vec3(1, 0, 0)),
      tightness_(desc.tightness), shadowless_(desc.shadowless) {
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
        areaNormal_ = glm::cross(edgeA_, edgeB_);
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
    const double tight = tightness_ > 0 ? std::pow(c, tightness_) : 1;
    if (c >= cosInner_) return tight;
    double x = (c - cosOuter_) / (cosInner_ - cosOuter_);
    return tight * x * x * (3 - 2 * x); // smoothstep
}

LightSample Light::sample(const Vec3& point, int index, const Vec2& jitter) const {
    if (kind_ == scene::LightKind::Parallel) {
        LightSample s;
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
    return toward(point, target, color);
}

LightSample Light::toward(const Vec3& point, const Vec3& target, Vec3 color) const {
    LightSample s;
    Vec3 offset = target - point;
    s.distance = glm::length(offset);
    s.toLight = s.distance > 0 ? offset / s.distance : Vec3(0, 1, 0);
    s.target = target;
    if (kind_ == scene::LightKind::Spot) color *= spotFactor(-s.toLight);
    s.color = color;
    return s;
}

LightSample Light::sampleUniformly(const Vec3& point, const Vec2& u) const {
    if (kind_ != scene::LightKind::Area && kind_ != scene::LightKind::Cylinder) return sample(point, 0, u);
    const Vec3 target = position_ + u.x * edgeA_ + (kind_ == scene::LightKind::Area ? u.y : 0.0) * edgeB_;
    return toward(point, target, color_);
}

double Light::crossing(const Ray& ray, double tMax) const {
    if (kind_ != scene::LightKind::Area) return kInfinity;
    const double facing = glm::dot(areaNormal_, ray.dir);
    if (facing == 0) return kInfinity;
    const double t = glm::dot(areaNormal_, position_ - ray.origin) / facing;
    if (!(t > 0 && t < tMax)) return kInfinity;
    // The point's coordinates along the edges: p = a·edgeA + b·edgeB.
    const Vec3 p = ray.origin + t * ray.dir - position_;
    const double squared = glm::dot(areaNormal_, areaNormal_);
    const double a = glm::dot(glm::cross(p, edgeB_), areaNormal_) / squared;
    const double b = glm::dot(glm::cross(edgeA_, p), areaNormal_) / squared;
    return a >= 0 && a <= 1 && b >= 0 && b <= 1 ? t : kInfinity;
}

double Light::areaPdf(const Vec3& toLight, double distance) const {
    const double projected = std::abs(glm::dot(areaNormal_, toLight)); // area · |cos θ|
    return projected > 0 ? distance * distance / projected : kInfinity;
}

} // namespace crt::tracer
