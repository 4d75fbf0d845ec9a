// Light along a ray through a medium (Integrator::throughMedium): the ray is cut into
// `samples` steps, each read at one jittered point. Over a step the coefficients are taken
// as constant, so a homogeneous medium's absorption and emission are exact, and its
// in-scattered light is exact wherever the light at the points does not change along it.
#include "tracer/integrator.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Vec3 Integrator::throughMedium(const Ray& ray, double distance, const Medium& medium, const Vec3& behind,
                               double pathLength, TraceContext& context) const {
    const double length = std::min(distance, kLongestMediumStretch);
    const int steps = medium.samples();
    const double step = length / steps;
    const double jitter = context.rng.uniform();
    Vec3 through(1.0), gathered(0.0);
    for (int i = 0; i < steps; ++i) {
        const double s = (i + jitter) * step;
        const Vec3 p = ray.at(s);
        const double density = medium.density(p);
        if (density <= 0) continue;
        Vec3 source = medium.emission() * density;
        if (medium.scattering() != Vec3(0.0))
            source += medium.scattering() * density * lightInMedium(p, ray.dir, medium, pathLength + s, context);
        const Vec3 extinction = medium.extinction() * density;
        gathered += through * source * integratedTransmittance(extinction, step);
        through *= transmittanceOver(extinction, step);
    }
    return gathered + through * behind;
}

Vec3 Integrator::lightInMedium(const Vec3& p, const Vec3& viewDir, const Medium& medium, double pathLength,
                               TraceContext& context) const {
    Vec3 sum(0.0);
    for (const Light& light : lights_) {
        const LightSample ls = light.sampleUniformly(p, context.rng.uniform2());
        if (ls.color == Vec3(0.0)) continue;
        Vec3 seen(1.0);
        if (!light.shadowless()) {
            const Ray shadow = ls.atInfinity ? Ray{p, ls.toLight, context.time} : Ray{p, ls.target - p, context.time};
            seen = transmittance(shadow, ls.atInfinity ? kInfinity : 1.0, {}, context);
            if (seen == Vec3(0.0)) continue;
        }
        // The medium between the point and where the shadow ray leaves its solid, read at
        // the point (exact for a homogeneous medium).
        Hit exit;
        const double inside = scene_.intersect(Ray{p, ls.toLight, context.time}, ls.distance, exit, context.scratch, context.stats)
                                  ? exit.t
                                  : ls.distance;
        const Vec3 extinction = medium.extinction() * medium.density(p);
        for (int c = 0; c < 3; ++c) seen[c] *= extinction[c] > 0 ? std::exp(-extinction[c] * inside) : 1.0;
        const double strength = lightStrength(light, ls.distance, pathLength) * medium.phase(glm::dot(ls.toLight, viewDir));
        sum += seen * ls.color * strength;
    }
    return sum;
}

} // namespace crt::tracer
