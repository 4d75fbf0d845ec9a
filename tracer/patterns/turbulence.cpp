// Turbulence from three decorrelated Perlin noises, one per axis.
#include "tracer/patterns/turbulence.hpp"

#include "tracer/noise.hpp"

namespace crt::tracer {

namespace {

/// Three noises in about [-1, 1]; the offsets keep the axes from moving together.
Vec3 vectorNoise(const Vec3& p) {
    return {perlinNoise(p), perlinNoise(p + Vec3(31.416, -17.32, 5.87)),
            perlinNoise(p + Vec3(-9.13, 44.71, -23.9))};
}

} // namespace

Vec3 turbulentPoint(const Vec3& p, const scene::TextureDesc& desc) {
    Vec3 sum(0.0);
    double amplitude = 1, frequency = 1;
    for (int i = 0; i < desc.octaves; ++i) {
        sum += vectorNoise(p * frequency) * amplitude;
        amplitude *= desc.omega;
        frequency *= desc.lambda;
    }
    return p + desc.displacement * sum;
}

} // namespace crt::tracer
