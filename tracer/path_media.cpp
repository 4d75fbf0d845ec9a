// The path integrator in media: where a path scatters in a medium, found by delta tracking,
// the medium's emission on the way, and the light shadow rays bring through media and
// absorbing solids (docs/rendering.md, "Media").
//
// A homogeneous medium is followed in closed form: the distance to scattering is drawn with
// the largest channel of its scattering coefficient, and the rest of its extinction
// (absorption, and the other channels' difference) weighs the path; a purely absorbing one
// only dims it. A medium whose density is a pattern is tracked against its bound: tentative
// collisions at the bound's rate, each real with the share of it the point has (Woodcock's
// delta tracking, its channels weighed as in Kutz et al.'s spectral tracking); shadow rays
// through it take the product of the null shares (ratio tracking).
#include "tracer/path_integrator.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

double largest(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

} // namespace

const Medium* PathIntegrator::mediumOf(int32_t material) const {
    if (material < 0) return nullptr;
    const int32_t medium = scene_.materials[static_cast<size_t>(material)].medium;
    return medium >= 0 ? &media_[static_cast<size_t>(medium)] : nullptr;
}

PathIntegrator::MediumStep PathIntegrator::trackMedium(const Ray& ray, double reach, const Medium& medium, Vec3& beta,
                                                       Vec3& radiance, TraceContext& context) const {
    const double speed = glm::length(ray.dir);
    const double end = std::min(reach, kLongestMediumStretch / speed);
    if (medium.homogeneous()) {
        // Distances in scene units from here on.
        const double length = end * speed, density = medium.density(ray.origin);
        const Vec3 extinction = medium.extinction() * density, scattering = medium.scattering() * density;
        const double rate = largest(scattering);
        double travelled = length;
        if (rate > 0) travelled = std::min(length, -std::log1p(-context.rng.uniform()) / rate);
        // Whatever it meets, the path's weight is what the medium lets through over the
        // chance of getting that far (exp(−rate·s)); its emission is gathered on the way.
        const Vec3 beyondRate = extinction - Vec3(rate);
        radiance += beta * medium.emission() * density * integratedTransmittance(beyondRate, travelled);
        beta *= transmittanceOver(beyondRate, travelled);
        if (travelled >= length) return {};
        beta *= scattering / rate;
        return {true, travelled / speed};
    }
    const double bound = largest(medium.extinction()) * medium.densityBound();
    if (!(bound > 0)) {
        // Nothing dims or scatters: the emission alone, at jittered points.
        const int steps = medium.samples();
        const double step = end / steps, jitter = context.rng.uniform();
        for (int i = 0; i < steps; ++i)
            radiance += beta * medium.emission() * medium.density(ray.at((i + jitter) * step)) * (step * speed);
        return {};
    }
    const double rate = bound * speed; // per unit of t
    for (double t = 0;;) {
        t -= std::log1p(-context.rng.uniform()) / rate;
        if (t >= end) return {};
        const double density = medium.density(ray.at(t));
        const Vec3 extinction = medium.extinction() * density, scattering = medium.scattering() * density;
        radiance += beta * medium.emission() * (density / bound);
        const double real = largest(scattering) / bound;
        if (context.rng.uniform() < real) {
            beta *= scattering / (bound * real);
            return {true, t};
        }
        beta *= (Vec3(bound) - extinction) / (bound * (1 - real));
        if (beta == Vec3(0.0)) return {};
    }
}

Vec3 PathIntegrator::mediumTransmittance(const Ray& ray, double from, double to, const Medium& medium,
                                         TraceContext& context) const {
    const double speed = glm::length(ray.dir);
    to = std::min(to, from + kLongestMediumStretch / speed);
    if (medium.homogeneous())
        return transmittanceOver(medium.extinction() * medium.density(ray.origin), (to - from) * speed);
    const double bound = largest(medium.extinction()) * medium.densityBound();
    if (!(bound > 0)) return Vec3(1.0);
    Vec3 through(1.0);
    for (double t = from;;) {
        t -= std::log1p(-context.rng.uniform()) / (bound * speed);
        if (t >= to) return through;
        through *= Vec3(1.0) - medium.extinction() * (medium.density(ray.at(t)) / bound);
        if (through == Vec3(0.0)) return through;
    }
}

Vec3 PathIntegrator::throughSolids(const Ray& ray, double tMax, std::vector<BoundaryCrossing>& crossings,
                                   TraceContext& context) const {
    std::sort(crossings.begin(), crossings.end(), [](const BoundaryCrossing& a, const BoundaryCrossing& b) {
        return a.material != b.material ? a.material < b.material : a.t < b.t;
    });
    const double speed = glm::length(ray.dir);
    // What a solid of `material` lets through from t = from to t = to.
    auto inside = [&](int32_t material, double from, double to) {
        if (const Medium* medium = mediumOf(material)) return mediumTransmittance(ray, from, to, *medium, context);
        if (to == kInfinity) return Vec3(1.0);
        return transmittanceOver(rgb(scene_.materials[static_cast<size_t>(material)].absorption), (to - from) * speed);
    };
    Vec3 through(1.0);
    for (size_t i = 0; i < crossings.size() && through != Vec3(0.0);) {
        // One solid's crossings in order: inside from its start when it first leaves.
        const int32_t material = crossings[i].material;
        double enteredAt = crossings[i].entering ? -1 : 0;
        for (; i < crossings.size() && crossings[i].material == material; ++i) {
            const BoundaryCrossing& c = crossings[i];
            if (c.entering) {
                enteredAt = c.t;
            } else if (enteredAt >= 0) {
                through *= inside(material, enteredAt, c.t);
                enteredAt = -1;
            }
        }
        if (enteredAt >= 0) through *= inside(material, enteredAt, tMax); // still inside where the ray ends
    }
    return through;
}

} // namespace crt::tracer
