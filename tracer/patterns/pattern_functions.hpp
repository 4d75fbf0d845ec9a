// The patterns' own definitions, before turbulence and waveform (used by pattern.cpp).
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/ray.hpp"

namespace crt::tracer::patterns {

// Tilings (tilings.cpp): the position of the colour, 0, 1 or 2.
double checker(const Vec3& p, double size);
double stripes(const Vec3& p, const Vec3& axis, double size);
double brick(const Vec3& p, const Vec3& brickSize, double mortar);
double hexagon(const Vec3& p);

// Distances (distance_patterns.cpp), POV-Ray 3.7's definitions.
double gradient(const Vec3& p, const Vec3& axis);
double onion(const Vec3& p);
double boxed(const Vec3& p);
double spherical(const Vec3& p);
double cylindrical(const Vec3& p);
double planar(const Vec3& p);

// Angles (angular_patterns.cpp): around an axis, and the surface's against a direction.
double radial(const Vec3& p);
double spiral(const Vec3& p, int arms);
double slope(const Vec3& normal, const Vec3& direction);

// Periodic (periodic_patterns.cpp).
double leopard(const Vec3& p);
double quilted(const Vec3& p, double control0, double control1);

// Circular waves from POV-Ray's ten sources (wave_patterns.cpp), given the pattern's
// frequency and phase, which they read inside.
double ripples(const Vec3& p, double frequency, double phase);
double waves(const Vec3& p, double frequency, double phase);

// Fractal (mandel_pattern.cpp).
double mandel(const Vec3& p, int iterations);

// The 2015 noise textures (noise_patterns.cpp), each with its own size and turbulence.
double noise(const Vec3& p, const scene::TextureDesc& desc);
double marble(const Vec3& p, const scene::TextureDesc& desc);
double wood(const Vec3& p, const scene::TextureDesc& desc);

// POV-Ray's noise patterns over crt's noise (noise_patterns.cpp): the same recipes.
double bozo(const Vec3& p);
double granite(const Vec3& p);
double agate(const Vec3& p);
double wrinkles(const Vec3& p);
double dents(const Vec3& p);

// A Function's value (function_pattern.cpp); above 1 its fraction, as in POV-Ray.
double function(const Vec3& p, const scene::FunctionProgram& f);

// Cellular (cellular_patterns.cpp): a random point or value in each unit cube.
double crackle(const Vec3& p, double metric, const Vec3& form);
double cells(const Vec3& p);

} // namespace crt::tracer::patterns
