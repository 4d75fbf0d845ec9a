// The noise textures of 2015: each scales by its size and wanders by its own turbulence.
#include "tracer/patterns/pattern_functions.hpp"

#include "tracer/noise.hpp"

#include <cmath>

namespace crt::tracer::patterns {

double noise(const Vec3& p, const scene::TextureDesc& desc) {
    return fractalNoise(p / desc.size, desc.octaves);
}

double marble(const Vec3& p, const scene::TextureDesc& desc) {
    double s = desc.size;
    return 0.5 +
           0.5 * std::sin((p.x / s + desc.turbulence * turbulence(p / s, desc.octaves) * 4) * kPi);
}

double wood(const Vec3& p, const scene::TextureDesc& desc) {
    double s = desc.size;
    double r = std::sqrt(p.x * p.x + p.z * p.z) / s;
    double t = desc.rings * r + desc.turbulence * 4 * (fractalNoise(p / s, 3) - 0.5);
    t -= std::floor(t);
    return t < 0.5 ? 2 * t : 2 - 2 * t;
}

} // namespace crt::tracer::patterns
