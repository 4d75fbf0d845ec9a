// Perlin gradient noise (Ken Perlin's improved noise, 2002) and fractal sums of it.
#pragma once

#include "tracer/geometry/ray.hpp"

namespace crt::tracer {

/// Noise in about [-1, 1], zero at integer lattice points.
double perlinNoise(const Vec3& p);
/// Sum of `octaves` octaves of noise, each at double frequency and half amplitude, in [0, 1].
double fractalNoise(const Vec3& p, int octaves);
/// Sum of |noise| over octaves (Perlin's turbulence), about [0, 1].
double turbulence(const Vec3& p, int octaves);

} // namespace crt::tracer
