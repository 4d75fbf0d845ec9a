// Perlin's improved noise with a fixed permutation, so textures look the same everywhere.
#include "tracer/noise.hpp"

#include "tracer/sampling.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace crt::tracer {

namespace {

std::array<uint8_t, 512> makePermutation() {
    std::array<uint8_t, 512> p{};
    for (int i = 0; i < 256; ++i) p[i] = static_cast<uint8_t>(i);
    uint64_t state = 0x5EED;
    for (int i = 255; i > 0; --i) {
        state = mix64(state);
        std::swap(p[i], p[state % (i + 1)]);
    }
    for (int i = 0; i < 256; ++i) p[256 + i] = p[i];
    return p;
}

const std::array<uint8_t, 512> kPermutation = makePermutation();

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double lerp(double t, double a, double b) { return a + t * (b - a); }
double grad(int hash, double x, double y, double z) {
    int h = hash & 15;
    double u = h < 8 ? x : y;
    double v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

} // namespace

double perlinNoise(const Vec3& point) {
    double fx = std::floor(point.x), fy = std::floor(point.y), fz = std::floor(point.z);
    int X = static_cast<int>(static_cast<long long>(fx) & 255), Y = static_cast<int>(static_cast<long long>(fy) & 255),
        Z = static_cast<int>(static_cast<long long>(fz) & 255);
    double x = point.x - fx, y = point.y - fy, z = point.z - fz;
    double u = fade(x), v = fade(y), w = fade(z);
    const auto& p = kPermutation;
    int A = p[X] + Y, AA = p[A] + Z, AB = p[A + 1] + Z, B = p[X + 1] + Y, BA = p[B] + Z, BB = p[B + 1] + Z;
    return lerp(w,
                lerp(v, lerp(u, grad(p[AA], x, y, z), grad(p[BA], x - 1, y, z)),
                     lerp(u, grad(p[AB], x, y - 1, z), grad(p[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(p[AA + 1], x, y, z - 1), grad(p[BA + 1], x - 1, y, z - 1)),
                     lerp(u, grad(p[AB + 1], x, y - 1, z - 1), grad(p[BB + 1], x - 1, y - 1, z - 1))));
}

double fractalNoise(const Vec3& p, int octaves) {
    double sum = 0, amplitude = 1, total = 0;
    Vec3 q = p;
    for (int i = 0; i < std::max(octaves, 1); ++i) {
        sum += amplitude * perlinNoise(q);
        total += amplitude;
        amplitude *= 0.5;
        q *= 2.0;
    }
    return std::clamp(0.5 + 0.5 * sum / total, 0.0, 1.0);
}

double turbulence(const Vec3& p, int octaves) {
    double sum = 0, amplitude = 1, total = 0;
    Vec3 q = p;
    for (int i = 0; i < std::max(octaves, 1); ++i) {
        sum += amplitude * std::abs(perlinNoise(q));
        total += amplitude;
        amplitude *= 0.5;
        q *= 2.0;
    }
    return sum / total;
}

} // namespace crt::tracer
