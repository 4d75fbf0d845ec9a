// How a material divides the light at a surface between mirror reflection and transmission
// (spec §6): read alike by the Whitted and the path integrators.
#pragma once

#include "tracer/render_scene.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

/// Mirror reflection at a point seen along `toViewer` where its normal is `n`: from
/// reflectivitymin facing the viewer to reflectivity at grazing (POV-Ray's
/// reflection { min max falloff }).
inline double reflectivityAt(const ShadingMaterial& m, const Vec3& toViewer, const Vec3& n) {
    if (m.reflectivityMin < 0 || m.reflectivityMin == m.reflectivity) return m.reflectivity;
    double cosView = std::clamp(glm::dot(toViewer, n), 0.0, 1.0);
    return m.reflectivityMin +
           (m.reflectivity - m.reflectivityMin) * std::pow(1 - cosView, m.reflectionFalloff);
}

/// The shares of mirror reflection (kr) and transmission (kt) at a surface, and where the
/// transmitted light goes.
struct SurfaceSplit {
    double reflectivity = 0; ///< the material's at this angle (reflectivityAt)
    double kr = 0, kt = 0;
    Vec3 refracted{0.0}; ///< unit; set when `refracts`
    bool refracts = false;
};

/// Snell's law against air for a ray of direction `d` meeting the surface whose normal `n`
/// faces it; a surface without inside (`solid` false: a quad, a disc) is a thin sheet. Total
/// internal reflection gives transmission's share to reflection; with `fresnel`, the
/// dielectric Fresnel factor moves part of it there too.
inline SurfaceSplit splitAt(const ShadingMaterial& m, const Vec3& d, const Vec3& n, bool entering, bool solid) {
    const double reflectivity = reflectivityAt(m, -d, n);
    SurfaceSplit split{reflectivity, reflectivity, m.transparency};
    if (split.kt <= 0) return split;
    double eta = solid ? (entering ? 1.0 / m.ior : m.ior) : 1.0;
    double cosI = std::min(1.0, glm::dot(-d, n));
    double sin2T = eta * eta * std::max(0.0, 1 - cosI * cosI);
    if (sin2T >= 1) {
        split.kr += split.kt; // total internal reflection
        split.kt = 0;
        return split;
    }
    double cosT = std::sqrt(1 - sin2T);
    split.refracted = glm::normalize(eta * d + (eta * cosI - cosT) * n);
    split.refracts = true;
    if (m.fresnel) {
        double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
        double rp = (eta * cosT - cosI) / (eta * cosT + cosI);
        double f = 0.5 * (rs * rs + rp * rp);
        split.kr += split.kt * f;
        split.kt *= 1 - f;
    }
    return split;
}

} // namespace crt::tracer
