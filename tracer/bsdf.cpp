// The four lobes of a material under the path integrator.
#include "tracer/bsdf.hpp"

#include "tracer/lights.hpp"
#include "tracer/sampling.hpp"
#include "tracer/surface_split.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// The GGX (Trowbridge–Reitz) distribution of microfacet normals at cos θ from the normal.
double ggxD(double cosTheta, double alpha) {
    if (cosTheta <= 0) return 0;
    const double a2 = alpha * alpha, c2 = cosTheta * cosTheta;
    const double denom = c2 * (a2 - 1) + 1;
    return a2 / (kPi * denom * denom);
}

/// Smith's masking of GGX for a direction at cos θ from the normal.
double ggxG1(double cosTheta, double alpha) {
    if (cosTheta <= 0) return 0;
    const double a2 = alpha * alpha;
    return 2 * cosTheta / (cosTheta + std::sqrt(a2 + (1 - a2) * cosTheta * cosTheta));
}

/// A microfacet normal drawn with density D(h)·cos θh, in `frame`.
Vec3 sampleGgxNormal(const Frame& frame, double alpha, const Vec2& u) {
    const double cos2 = (1 - u.x) / (1 + (alpha * alpha - 1) * u.x);
    const double cosTheta = std::sqrt(std::max(0.0, cos2)), sinTheta = std::sqrt(std::max(0.0, 1 - cos2));
    const double phi = 2 * kPi * u.y;
    return frame.fromLocal({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
}

/// `w` moved to the side of the plane of normal `side` it should be on (sign +1: the side
/// `side` points to), by mirroring it in that plane: glossy lobes that stray across the
/// surface are folded back, as under the Whitted integrator.
Vec3 foldTo(const Vec3& w, const Vec3& side, double sign) {
    const double along = glm::dot(w, side) * sign;
    return along < 0 ? glm::normalize(w - 2 * along * sign * side) : w;
}

} // namespace

Bsdf::Bsdf(const ShadingMaterial& m, const Vec3& color, const Vec3& d, const Vec3& n, const Vec3& ng,
           bool entering, bool solid)
    : wo_(-d), n_(n), ng_(ng), frame_(Frame::fromAxis(n)) {
    const SurfaceSplit split = splitAt(m, d, n, entering, solid);
    double diffuse = m.conserveEnergy ? m.diffuse * std::max(0.0, 1 - split.reflectivity - m.transparency) : m.diffuse;
    double highlight = m.specular, reflect = split.kr, transmit = split.refracts ? split.kt : 0;
    // Energy conservation: the lobes together send on at most what arrives.
    const double total = diffuse + highlight + reflect + transmit;
    if (total > 1) {
        diffuse /= total, highlight /= total, reflect /= total, transmit /= total;
    }
    diffuseWeight_ = std::max(diffuse, 0.0), highlightWeight_ = std::max(highlight, 0.0);
    reflectWeight_ = std::max(reflect, 0.0), transmitWeight_ = std::max(transmit, 0.0);
    albedo_ = color * diffuseWeight_;
    tint_ = m.metallic ? color : Vec3(1.0);
    // Phong's exponent as a microfacet roughness (Walter et al. 2007: α = √(2 / (n + 2))); the
    // Whitted cone of half-angle glossiness · 45° as the GGX roughness whose reflected lobe
    // has about that half-width.
    highlightAlpha_ = std::clamp(std::sqrt(2 / (std::max(m.shininess, 0.0) + 2)), 1e-3, 1.0);
    glossAlpha_ = m.glossiness > 0 ? std::tan(std::clamp(m.glossiness, 0.0, 1.0) * kPi / 8) / 0.64 : 0;
    refracted_ = split.refracted;
    eta_ = solid ? (entering ? 1.0 / m.ior : m.ior) : 1.0;

    const double chances[4] = {luminance(albedo_), highlightWeight_ * luminance(tint_),
                               reflectWeight_ * luminance(tint_), transmitWeight_};
    const double sum = chances[0] + chances[1] + chances[2] + chances[3];
    if (sum > 0) {
        pickDiffuse_ = chances[0] / sum, pickHighlight_ = chances[1] / sum, pickReflect_ = chances[2] / sum;
    }
    if (sum <= 0) diffuseWeight_ = highlightWeight_ = reflectWeight_ = transmitWeight_ = 0;
}

Vec3 Bsdf::highlightCos(const Vec3& wi) const {
    const double cosO = glm::dot(n_, wo_), cosI = glm::dot(n_, wi);
    if (highlightWeight_ <= 0 || cosO <= 0 || cosI <= 0) return Vec3(0.0);
    const Vec3 h = glm::normalize(wo_ + wi);
    const double D = ggxD(glm::dot(n_, h), highlightAlpha_);
    const double G = ggxG1(cosO, highlightAlpha_) * ggxG1(cosI, highlightAlpha_);
    return highlightWeight_ * tint_ * (D * G / (4 * cosO));
}

double Bsdf::highlightPdf(const Vec3& wi) const {
    const Vec3 h = glm::normalize(wo_ + wi);
    const double woDotH = std::abs(glm::dot(wo_, h));
    if (woDotH <= 0) return 0;
    const double cosH = glm::dot(n_, h);
    return ggxD(cosH, highlightAlpha_) * cosH / (4 * woDotH);
}

Vec3 Bsdf::evalCos(const Vec3& wi) const {
    const double cosI = glm::dot(n_, wi);
    if (cosI <= 0 || glm::dot(ng_, wi) <= 0) return Vec3(0.0);
    return albedo_ * (cosI / kPi) + highlightCos(wi);
}

double Bsdf::pdf(const Vec3& wi) const {
    const double cosI = glm::dot(n_, wi);
    if (cosI <= 0 || glm::dot(ng_, wi) <= 0) return 0;
    double p = pickDiffuse_ * cosI / kPi;
    if (pickHighlight_ > 0) p += pickHighlight_ * highlightPdf(wi);
    return p;
}

bool Bsdf::sample(double pick, const Vec2& u, BsdfSample& out) const {
    if (pick < pickDiffuse_ + pickHighlight_) {
        if (pick < pickDiffuse_) {
            const Vec2 disc = concentricDisc(u);
            const double z = std::sqrt(std::max(0.0, 1 - disc.x * disc.x - disc.y * disc.y));
            out.wi = frame_.fromLocal({disc.x, disc.y, z});
        } else {
            const Vec3 h = sampleGgxNormal(frame_, highlightAlpha_, u);
            out.wi = 2 * glm::dot(wo_, h) * h - wo_;
        }
        out.pdf = pdf(out.wi);
        const Vec3 f = evalCos(out.wi);
        if (out.pdf <= 0 || f == Vec3(0.0)) return false;
        out.weight = f / out.pdf;
        out.transmitted = false;
        return true;
    }
    out.pdf = 0;
    if (pick < pickDiffuse_ + pickHighlight_ + pickReflect_) {
        Vec3 h = glossAlpha_ > 0 ? sampleGgxNormal(frame_, glossAlpha_, u) : n_;
        out.wi = foldTo(2 * glm::dot(wo_, h) * h - wo_, ng_, 1);
        out.weight = reflectWeight_ * tint_ / pickReflect_;
        out.transmitted = false;
        return true;
    }
    const double pickTransmit = transmitChance();
    if (transmitWeight_ <= 0 || pickTransmit <= 0) return false;
    Vec3 wi = refracted_;
    if (glossAlpha_ > 0) {
        // Frosted glass: refraction through a microfacet normal drawn around the normal.
        const Vec3 h = sampleGgxNormal(frame_, glossAlpha_, u);
        const double cosI = glm::dot(wo_, h), sin2T = eta_ * eta_ * std::max(0.0, 1 - cosI * cosI);
        if (cosI > 0 && sin2T < 1)
            wi = glm::normalize(-eta_ * wo_ + (eta_ * cosI - std::sqrt(1 - sin2T)) * h);
    }
    out.wi = foldTo(wi, ng_, -1);
    out.weight = Vec3(transmitWeight_ / pickTransmit);
    out.transmitted = true;
    out.sharpRefraction = glossAlpha_ <= 0;
    out.lobeChance = pickTransmit;
    return true;
}

bool Bsdf::sharpRefraction(SharpRefraction& out) const {
    const double chance = transmitChance();
    if (transmitWeight_ <= 0 || chance <= 0 || glossAlpha_ > 0) return false;
    out = {foldTo(refracted_, ng_, -1), transmitWeight_, chance};
    return true;
}

} // namespace crt::tracer
