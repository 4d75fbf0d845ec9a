// Owen-scrambled Sobol points, one dimension or a pair at a time, for the paths of a pixel:
// point i of every dimension (pair) is drawn from a stratified set over the pixel's paths
// (any 2^k consecutive points from 0 fill each of 2^k strata once; a pair's fill each of 2^k
// rectangles of area 2^-k), and a hash of the pixel and the dimension scrambles each
// dimension apart. The point's index is shuffled the same way first, so that the dimensions
// do not repeat one another's pattern. After Burley, "Practical Hash-based Owen Scrambling"
// (JCGT 2020).
#pragma once

#include "tracer/geometry/ray.hpp"

#include <cstdint>

namespace crt::tracer {

inline uint32_t reverseBits(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    return ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
}

/// Laine and Karras's hash (with Burley's constants) on a bit-reversed binary fraction: each
/// bit flipped by a hash of the bits below it and `seed`, which, reversed back, is a nested
/// uniform (Owen) scramble: each bit flipped by a hash of the bits above it.
inline uint32_t laineKarras(uint32_t reversed, uint32_t seed) {
    uint32_t x = reversed + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

inline uint32_t owenScramble(uint32_t x, uint32_t seed) { return reverseBits(laineKarras(reverseBits(x), seed)); }

/// A 32-bit hash (Wellons's lowbias32), and seeds for the several scrambles of one point.
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}
inline uint32_t hashSeed(uint32_t seed, uint32_t n) { return hash32(seed ^ hash32(n + 0x9e3779b9u)); }

/// The Sobol sequence's second dimension, as a binary fraction: point i is the sum (xor) of
/// the direction numbers v_k of the bits k set in i, v_0 = 2^31 and v_k = v_(k-1) xor
/// v_(k-1)/2; a byte of i at a time from tables of those sums.
class SobolSecondDimension {
public:
    constexpr SobolSecondDimension() : table_() {
        uint32_t v = 1u << 31;
        for (int byte = 0; byte < 4; ++byte) {
            uint32_t directions[8];
            for (uint32_t& d : directions) {
                d = v;
                v ^= v >> 1;
            }
            for (uint32_t b = 0; b < 256; ++b) {
                uint32_t sum = 0;
                for (int k = 0; k < 8; ++k)
                    if (b >> k & 1u) sum ^= directions[k];
                table_[byte][b] = sum;
            }
        }
    }
    uint32_t operator()(uint32_t i) const {
        return table_[0][i & 255u] ^ table_[1][i >> 8 & 255u] ^ table_[2][i >> 16 & 255u] ^ table_[3][i >> 24];
    }

private:
    uint32_t table_[4][256];
};
inline constexpr SobolSecondDimension sobolSecond;

inline double unitFraction(uint32_t x) { return x * 0x1.0p-32; }

/// Point `index` of the one-dimensional sequence scrambled by `seed`, in [0, 1): the first
/// Sobol dimension (the van der Corput sequence, the index reversed) of the shuffled index,
/// scrambled; the shuffle's own reversal cancels the van der Corput one.
inline double sobolPoint1(uint32_t index, uint32_t seed) {
    const uint32_t first = laineKarras(reverseBits(index), seed);
    return unitFraction(owenScramble(first, hashSeed(seed, 1)));
}

/// Point `index` of the two-dimensional sequence scrambled by `seed`, in [0, 1)².
inline Vec2 sobolPoint2(uint32_t index, uint32_t seed) {
    const uint32_t first = laineKarras(reverseBits(index), seed);
    const uint32_t shuffled = reverseBits(first);
    return {unitFraction(owenScramble(first, hashSeed(seed, 1))),
            unitFraction(owenScramble(sobolSecond(shuffled), hashSeed(seed, 2)))};
}

} // namespace crt::tracer
