// Point, parallel, spot, area and cylinder lights.
#include "tracer/lights.hpp"

#include "tracer/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Light::Light(const scene::LightDesc& desc, int shadowSamples)
    : kind_(desc.kind), color_(rgb(desc.color)), ambient_(desc.ambient), falloff_(desc.falloff),
      attenuation_(desc.attenuation),
      attenuates_(desc.kind != scene::LightKind::Parallel && desc.attenuation != Vec3(1, 0, 0)),
      tightness_(desc.tightness), shadowless_(desc.shadowless), circular_(desc.circular),
      orient_(desc.orient), visible_(desc.visible), radius_(desc.radius) {
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
    case scene::LightKind::Area:
    case scene::LightKind::Sphere: {
        position_ = desc.origin;
        edgeA_ = desc.edgeA;
        edgeB_ = desc.edgeB;
        if (desc.kind == scene::LightKind::Sphere) {
            // Lit as the disc through its centre facing each point, which is what the sphere
            // shows a point (POV-Ray's circular, oriented area light).
            edgeA_ = Vec3(2 * desc.radius, 0, 0);
            edgeB_ = Vec3(0, 0, 2 * desc.radius);
            position_ = desc.origin - 0.5 * (edgeA_ + edgeB_);
            circular_ = orient_ = true;
        }
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
    if (hasArea()) {
        int sx = index % strataX_, sy = index / strataX_;
        double a = (sx + jitter.x) / strataX_, b = (sy + jitter.y) / strataY_;
        target = areaPoint(areaFrame(point), std::min(a, 1.0), std::min(b, 1.0));
        color = color_ / static_cast<double>(sampleCount_);
    } else if (kind_ == scene::LightKind::Cylinder) {
        target = position_ + std::min((index + jitter.x) / sampleCount_, 1.0) * edgeA_;
        color = color_ / static_cast<double>(sampleCount_);
    }
    return toward(point, target, color);
}

Light::AreaFrame Light::areaFrame(const Vec3& point) const {
    if (!orient_) return {position_, edgeA_, edgeB_, areaNormal_};
    // Turned about its centre so that its normal points at `point`: the edges keep their
    // lengths and, as nearly as they can, their directions.
    const Vec3 center = position_ + 0.5 * (edgeA_ + edgeB_);
    const Vec3 toPoint = point - center;
    const double distance = glm::length(toPoint);
    if (distance == 0 || areaNormal_ == Vec3(0.0)) return {position_, edgeA_, edgeB_, areaNormal_};
    const Vec3 facing = toPoint / distance;
    Vec3 alongA = edgeA_ - glm::dot(edgeA_, facing) * facing;
    if (glm::dot(alongA, alongA) < 1e-12 * glm::dot(edgeA_, edgeA_))
        alongA = glm::cross(facing, std::abs(facing.x) > 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0));
    alongA = glm::normalize(alongA);
    const Vec3 alongB = glm::cross(facing, alongA);
    AreaFrame frame;
    frame.edgeA = alongA * glm::length(edgeA_);
    frame.edgeB = alongB * glm::length(edgeB_);
    frame.corner = center - 0.5 * (frame.edgeA + frame.edgeB);
    frame.normal = glm::cross(frame.edgeA, frame.edgeB);
    return frame;
}

Vec3 Light::areaPoint(const AreaFrame& frame, double a, double b) const {
    if (circular_) {
        const Vec2 disc = concentricDisc({a, b});
        a = 0.5 * (disc.x + 1);
        b = 0.5 * (disc.y + 1);
    }
    return frame.corner + a * frame.edgeA + b * frame.edgeB;
}

LightSample Light::toward(const Vec3& point, const Vec3& target, Vec3 color) const {
    const Vec3 offset = target - point;
    const double distance = glm::length(offset);
    const Vec3 toLight = distance > 0 ? offset / distance : Vec3(0, 1, 0);
    if (kind_ == scene::LightKind::Spot) color *= spotFactor(-toLight);
    // Made whole in place: filled with its defaults first, it would be cleared and then
    // written again.
    return {toLight, target, distance, color, false};
}

LightSample Light::sampleUniformly(const Vec3& point, const Vec2& u) const {
    if (!hasArea() && kind_ != scene::LightKind::Cylinder) return sample(point, 0, u);
    const Vec3 target = hasArea() ? areaPoint(areaFrame(point), u.x, u.y) : position_ + u.x * edgeA_;
    return toward(point, target, color_);
}

double Light::crossing(const Ray& ray, double tMax) const {
    if (!hasArea()) return kInfinity;
    const AreaFrame frame = areaFrame(ray.origin);
    const double facing = glm::dot(frame.normal, ray.dir);
    if (facing == 0) return kInfinity;
    const double t = glm::dot(frame.normal, frame.corner - ray.origin) / facing;
    if (!(t > 0 && t < tMax)) return kInfinity;
    // The point's coordinates along the edges: p = a·edgeA + b·edgeB.
    const Vec3 p = ray.origin + t * ray.dir - frame.corner;
    const double squared = glm::dot(frame.normal, frame.normal);
    const double a = glm::dot(glm::cross(p, frame.edgeB), frame.normal) / squared;
    const double b = glm::dot(glm::cross(frame.edgeA, p), frame.normal) / squared;
    if (circular_) return (2 * a - 1) * (2 * a - 1) + (2 * b - 1) * (2 * b - 1) <= 1 ? t : kInfinity;
    return a >= 0 && a <= 1 && b >= 0 && b <= 1 ? t : kInfinity;
}

double Light::areaPdf(const Vec3& point, const Vec3& toLight, double distance) const {
    // area · |cos θ|
    const double projected = std::abs(glm::dot(areaFrame(point).normal, toLight)) * sampledShare();
    return projected > 0 ? distance * distance / projected : kInfinity;
}

namespace {

/// The roots of a·t² + 2·halfB·t + c in increasing order, or none (false).
bool quadraticRoots(double a, double halfB, double c, double& t0, double& t1) {
    const double discriminant = halfB * halfB - a * c;
    if (a == 0 || discriminant < 0) return false;
    const double root = std::sqrt(discriminant);
    t0 = (-halfB - root) / a;
    t1 = (-halfB + root) / a;
    return true;
}

} // namespace

double Light::seenAt(const Ray& ray, double tMax) const {
    if (kind_ == scene::LightKind::Area) return crossing(ray, tMax);
    if (kind_ != scene::LightKind::Sphere && kind_ != scene::LightKind::Cylinder) return kInfinity;
    // The sphere around the centre, or the open tube around the segment (the parts of the
    // ray and of its origin across the segment).
    Vec3 d = ray.dir, f = ray.origin - position_;
    const double length2 = glm::dot(edgeA_, edgeA_);
    if (kind_ == scene::LightKind::Sphere) {
        f -= 0.5 * (edgeA_ + edgeB_);
    } else {
        d -= edgeA_ * (glm::dot(ray.dir, edgeA_) / length2);
        f -= edgeA_ * (glm::dot(f, edgeA_) / length2);
    }
    double t0, t1;
    if (!quadraticRoots(glm::dot(d, d), glm::dot(f, d), glm::dot(f, f) - radius_ * radius_, t0, t1)) return kInfinity;
    for (double t : {t0, t1}) {
        if (!(t > 0 && t < tMax)) continue;
        if (kind_ == scene::LightKind::Sphere) return t;
        const double along = glm::dot(ray.origin + t * ray.dir - position_, edgeA_) / length2;
        if (along >= 0 && along <= 1) return t;
    }
    return kInfinity;
}

double lightStrength(const Light& light, double distance, double pathLength) {
    double strength = kPi;
    if (light.falloff() > 0 && distance < kInfinity) {
        const double d = distance + pathLength;
        strength *= light.falloff() / (d * d);
    }
    if (light.attenuates()) strength *= light.attenuation(distance);
    return strength;
}

const Light* firstSeenLight(const std::vector<Light>& lights, const Ray& ray, double& tMax) {
    const Light* first = nullptr;
    for (const Light& light : lights) {
        if (!light.visible()) continue;
        const double t = light.seenAt(ray, tMax);
        if (t < tMax) {
            tMax = t;
            first = &light;
        }
    }
    return first;
}

} // namespace crt::tracer
