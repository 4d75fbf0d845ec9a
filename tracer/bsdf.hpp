// A material as the path integrator reads it: one energy-conserving BSDF of four lobes
// (docs/rendering.md, "Path tracing").
#pragma once

#include "tracer/geometry/geometry_math.hpp"
#include "tracer/render_scene.hpp"

namespace crt::tracer {

/// A direction the BSDF chose, and what the path's throughput is multiplied by for it.
struct BsdfSample {
    Vec3 wi{0.0};
    Vec3 weight{0.0}; ///< f·|cos θ| / pdf
    /// The density of the lobes light sampling also reaches (solid angle); 0 when a mirror or
    /// glass lobe chose the direction, which light sampling cannot.
    double pdf = 0;
    bool transmitted = false;
    /// Set when clear glass refracted the path exactly (no roughness spread it).
    bool sharpRefraction = false;
    /// The chance that sample() picked the refraction lobe, when it did.
    double lobeChance = 1;
};

/// Clear glass's refraction at a surface point: the one direction it sends light on, the
/// share it sends there, and the chance Bsdf::sample takes it.
struct SharpRefraction {
    Vec3 wi{0.0};
    double weight = 0;
    double chance = 0;
};

/// The lobes at one surface point seen from `wo`: Lambert diffuse, a GGX highlight (the
/// Phong highlight's `specular` and `shininess`), mirror or glossy reflection, and
/// refraction. Their weights add up to at most one.
class Bsdf {
public:
    /// `d`: the incoming ray's direction; `n` and `ng`: the shading and geometric normals turned
    /// against it; `color`: the material's colour there.
    Bsdf(const ShadingMaterial& m, const Vec3& color, const Vec3& d, const Vec3& n, const Vec3& ng, bool entering,
         bool solid);

    /// Whether any lobe light sampling can reach is present (diffuse or highlight).
    bool reachable() const { return diffuseWeight_ + highlightWeight_ > 0; }
    /// The share of light it sends on, lobe by lobe: each lobe's weight times its colour.
    Vec3 albedo() const { return albedo_ + (highlightWeight_ + reflectWeight_) * tint_ + Vec3(transmitWeight_); }
    /// f(wo, wi)·cos θi of the lobes light sampling reaches.
    Vec3 evalCos(const Vec3& wi) const;
    /// The density with which sample() chooses wi through those lobes.
    double pdf(const Vec3& wi) const;
    /// A direction by two uniform numbers and a third that picks the lobe; false when the
    /// material sends no light on (black, or a direction below the surface).
    bool sample(double pick, const Vec2& u, BsdfSample& out) const;
    /// The refraction, when it is clear glass's (no roughness) and sends light on here; false
    /// otherwise.
    bool sharpRefraction(SharpRefraction& out) const;

private:
    double transmitChance() const { return 1 - pickDiffuse_ - pickHighlight_ - pickReflect_; }
    double highlightPdf(const Vec3& wi) const;
    Vec3 highlightCos(const Vec3& wi) const;

    Vec3 wo_, n_, ng_;
    Frame frame_; ///< around n_
    Vec3 albedo_{0.0}; ///< diffuse: colour · its weight
    Vec3 tint_{1.0};   ///< highlight and reflection: the colour for metals, else white
    double diffuseWeight_ = 0, highlightWeight_ = 0, reflectWeight_ = 0, transmitWeight_ = 0;
    double highlightAlpha_ = 1, glossAlpha_ = 0;
    Vec3 refracted_{0.0};
    double eta_ = 1; ///< the ratio of refractive indices, this side over the other
    /// The chances of picking each lobe (transmission takes the rest).
    double pickDiffuse_ = 0, pickHighlight_ = 0, pickReflect_ = 0;
};

} // namespace crt::tracer
