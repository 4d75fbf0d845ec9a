// Noise patterns: the textures of 2015, each with its own size and turbulence, and POV-Ray's
// noise patterns made by its recipes over crt's Perlin noise.
#include "tracer/patterns/pattern_functions.hpp"

#include "tracer/noise.hpp"
#include "tracer/patterns/waveform.hpp"

#include <algorithm>
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
    return triangleWave(desc.rings * r + desc.turbulence * 4 * (fractalNoise(p / s, 3) - 0.5));
}

namespace {

/// Perlin noise as a value in [0, 1] about 0.5, as POV-Ray's noise is.
double unitNoise(const Vec3& p) {
    return std::clamp(0.5 + 0.5 * perlinNoise(p), 0.0, 1.0);
}

} // namespace

double bozo(const Vec3& p) {
    return unitNoise(p);
}

double granite(const Vec3& p) {
    // Six octaves of |noise - 1/2| from four times the frequency: sharp creases.
    double sum = 0, frequency = 1;
    for (int i = 0; i < 6; ++i, frequency *= 2)
        sum += std::abs(0.5 - unitNoise(p * (4 * frequency))) / frequency;
    return sum;
}

double agate(const Vec3& p) {
    // Bands along z, pushed about by turbulence, sharpened towards their light side.
    double bands = 0.5 * (std::sin(2 * kPi * (1.3 * turbulence(p, 6) + 1.1 * p.z)) + 1);
    return std::pow(std::clamp(bands, 0.0, 1.0), 0.77);
}

double wrinkles(const Vec3& p) {
    double sum = unitNoise(p), amplitude = 0.5, frequency = 2;
    for (int i = 1; i < 10; ++i, amplitude *= 0.5, frequency *= 2)
        sum += amplitude * unitNoise(p * frequency);
    return sum / 2;
}

double dents(const Vec3& p) {
    double n = unitNoise(p);
    return n * n * n;
}

} // namespace crt::tracer::patterns
