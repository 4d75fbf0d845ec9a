// Deterministic sample generation: every random number derives from (seed, pixel, sample,
// dimension), never from thread scheduling, so images are identical for any thread count.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "tracer/sobol_sequence.hpp"

#include <cstdint>

namespace crt::tracer {

/// SplitMix64's finaliser: a strong 64-bit mix.
constexpr uint64_t mix64(uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// The numbers of one pixel sample: independent ones from a small counter-based generator,
/// or, for a path, the successive dimensions of the pixel's scrambled Sobol sequence
/// (sobol_sequence.hpp), so that a pixel's paths spread evenly over each of their choices.
class SampleRng {
public:
    SampleRng(uint64_t seed, uint64_t pixel, uint64_t sample)
        : state_(mix64(mix64(mix64(seed) ^ pixel) ^ (sample * 0xD1B54A32D192ED03ull))) {}

    /// Path `path` of a pixel: point `path` of each dimension of its sequence in turn.
    static SampleRng sequence(uint64_t seed, uint64_t pixel, uint32_t path) {
        SampleRng rng(seed, pixel, path);
        rng.sequenced_ = true;
        rng.pixelSeed_ = static_cast<uint32_t>(mix64(mix64(seed) ^ pixel) >> 32);
        rng.index_ = path;
        return rng;
    }
    /// Makes dimension `d` of the sequence the next: a path that starts each of its bounces
    /// at the same dimension draws the same choices from the same dimensions as the pixel's
    /// other paths, whatever it drew before.
    void skipTo(uint32_t d) { dimension_ = d; }

    uint64_t next() { return mix64(state_ += 0x9E3779B97F4A7C15ull); }
    /// Uniform in [0, 1).
    double uniform() {
        if (sequenced_) return sobolPoint1(index_, hashSeed(pixelSeed_, dimension_++));
        return static_cast<double>(next() >> 11) * 0x1.0p-53;
    }
    Vec2 uniform2() {
        if (sequenced_) return sobolPoint2(index_, hashSeed(pixelSeed_, dimension_++));
        double a = uniform();
        return {a, uniform()};
    }

private:
    uint64_t state_;
    bool sequenced_ = false;
    uint32_t pixelSeed_ = 0, index_ = 0, dimension_ = 0;
};

/// Van der Corput radical inverse in base 2.
inline double radicalInverse2(uint32_t i) { return unitFraction(reverseBits(i)); }

/// Point i of an n-point Hammersley set, toroidally shifted by `shift` (Cranley–Patterson
/// rotation): low discrepancy within a pixel, decorrelated between pixels.
inline Vec2 hammersley(uint32_t i, uint32_t n, const Vec2& shift) {
    Vec2 p((i + 0.5) / n, radicalInverse2(i));
    p += shift;
    if (p.x >= 1) p.x -= 1;
    if (p.y >= 1) p.y -= 1;
    return p;
}

/// A uniform point on the unit disc (Shirley–Chiu concentric map: keeps stratification).
inline Vec2 concentricDisc(const Vec2& u) {
    Vec2 o = 2.0 * u - Vec2(1.0);
    if (o.x == 0 && o.y == 0) return Vec2(0.0);
    double r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = (kPi / 4) * (o.y / o.x);
    } else {
        r = o.y;
        theta = kPi / 2 - (kPi / 4) * (o.x / o.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

} // namespace crt::tracer
