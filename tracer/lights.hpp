// Lights of spec §5, prepared for shading: where light comes from at a point, and how much.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "scene/scene_desc.hpp"

#include <vector>

namespace crt::tracer {

inline Vec3 rgb(const scene::Color& c) { return {c.r, c.g, c.b}; }
/// The brightness of a linear colour as the eye weighs it (Rec. 709).
inline double luminance(const Vec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/// One sample of a light seen from a point.
struct LightSample {
    Vec3 toLight{0.0};  ///< unit direction from the point to the light
    Vec3 target{0.0};   ///< the light's position (unused for parallel lights)
    double distance = kInfinity;
    Vec3 color{0.0};    ///< the light's color for this sample, cone factor included
    bool atInfinity = false;
};

class Light {
public:
    explicit Light(const scene::LightDesc& desc, int shadowSamples);

    /// How many samples shading takes: shadowsamples for an area or cylinder light, else one.
    int sampleCount() const { return sampleCount_; }
    /// Sample `index` of sampleCount(), at `point`; `jitter` in [0,1)² places it in its stratum.
    LightSample sample(const Vec3& point, int index, const Vec2& jitter) const;
    /// Path tracing's sample at `point`: a point of an area light's parallelogram or of a
    /// cylinder light's segment drawn uniformly by `u` in [0,1)², carrying the whole colour
    /// (the light's own position for the others).
    LightSample sampleUniformly(const Vec3& point, const Vec2& u) const;

    /// Whether rays can meet what it samples: an area light's parallelogram (or ellipse), or
    /// the disc of a sphere light facing the point it lights.
    bool hasArea() const { return kind_ == scene::LightKind::Area || kind_ == scene::LightKind::Sphere; }
    /// Where `ray` crosses what an area or sphere light samples within (0, tMax), or kInfinity.
    double crossing(const Ray& ray, double tMax) const;
    /// Whether camera and reflected rays see it (`visible`).
    bool visible() const { return visible_; }
    /// Where `ray` meets the light as it is seen within (0, tMax): an area light's
    /// parallelogram, a sphere light's sphere, a cylinder light's tube; else kInfinity.
    double seenAt(const Ray& ray, double tMax) const;
    /// The solid-angle density of sampleUniformly's points of an area light seen from
    /// `point`, at `distance` along the unit direction `toLight`: d² / (area · |cos θ|).
    double areaPdf(const Vec3& point, const Vec3& toLight, double distance) const;
    /// Whether it is an area light whose plane is the same whatever point it lights (no
    /// `orient`), of some area: one a path through glass can be solved onto.
    bool fixedPlane() const {
        return kind_ == scene::LightKind::Area && !orient_ && areaNormal_ != Vec3(0.0);
    }
    /// The unit normal of a fixed plane's light.
    Vec3 planeNormal() const { return glm::normalize(areaNormal_); }
    /// The density by area of the points sampleUniformly draws on a fixed plane's light.
    double pointDensity() const { return 1 / (glm::length(areaNormal_) * sampledShare()); }

    Vec3 color() const { return color_; }
    double ambient() const { return ambient_; }
    double falloff() const { return falloff_; }
    /// Whether attenuation differs from none, vec3(1, 0, 0).
    bool attenuates() const { return attenuates_; }
    /// The factor 1 / (c0 + c1·d + c2·d²) at `distance` from the light.
    double attenuation(double distance) const {
        return 1 / (attenuation_.x + distance * (attenuation_.y + distance * attenuation_.z));
    }
    scene::LightKind kind() const { return kind_; }
    /// Whether it shines from one point, its position (a point or a spot light).
    bool fromPoint() const { return kind_ == scene::LightKind::Point || kind_ == scene::LightKind::Spot; }
    const Vec3& position() const { return position_; }
    /// Its colour in the unit direction `fromLight` (a spot light's cone included).
    Vec3 colorToward(const Vec3& fromLight) const {
        return kind_ == scene::LightKind::Spot ? color_ * spotFactor(fromLight) : color_;
    }
    /// Whether it lights without shadow rays (`shadowless`).
    bool shadowless() const { return shadowless_; }

private:
    /// The share of the parallelogram its points are drawn from: the inscribed ellipse's π/4
    /// when `circular`.
    double sampledShare() const { return circular_ ? kPi / 4 : 1.0; }
    /// An area light's parallelogram as seen from `point` (turned to face it when `orient`).
    struct AreaFrame {
        Vec3 corner, edgeA, edgeB;
        Vec3 normal; ///< edgeA × edgeB: as long as the parallelogram's area
    };
    AreaFrame areaFrame(const Vec3& point) const;
    /// The point of the area light at (a, b) in [0,1]² of `frame`: its parallelogram's, or
    /// with `circular` the inscribed ellipse's (the square mapped onto the disc).
    Vec3 areaPoint(const AreaFrame& frame, double a, double b) const;
    double spotFactor(const Vec3& fromLight) const;
    /// The sample of the point `target` of the light, of colour `color`, seen from `point`.
    LightSample toward(const Vec3& point, const Vec3& target, Vec3 color) const;

    scene::LightKind kind_;
    Vec3 position_{0.0}, direction_{0.0}, edgeA_{0.0}, edgeB_{0.0};
    Vec3 areaNormal_{0.0}; ///< edgeA × edgeB: the parallelogram's normal, as long as its area
    Vec3 color_{0.0};
    double ambient_ = 0, falloff_ = 0;
    Vec3 attenuation_{1, 0, 0};
    bool attenuates_ = false;
    double cosOuter_ = -1, cosInner_ = -1, tightness_ = 0;
    bool shadowless_ = false;
    bool circular_ = false, orient_ = false, visible_ = false;
    double radius_ = 0; ///< Sphere, Cylinder
    int sampleCount_ = 1, strataX_ = 1, strataY_ = 1;
};

/// What a light of colour L sends to a point `distance` from it (kInfinity: a parallel
/// light), reached by a path `pathLength` long, per unit of L: π, so that it lights a white
/// Lambertian surface to L·cos θ, with the light's falloff and attenuation.
double lightStrength(const Light& light, double distance, double pathLength);

/// The visible light `ray` meets first within (0, tMax), narrowing tMax to where; null if none.
const Light* firstSeenLight(const std::vector<Light>& lights, const Ray& ray, double& tMax);

} // namespace crt::tracer
