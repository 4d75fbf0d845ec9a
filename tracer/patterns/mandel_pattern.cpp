// The Mandelbrot set in the x-y plane.
#include "tracer/patterns/pattern_functions.hpp"

namespace crt::tracer::patterns {

double mandel(const Vec3& p, int iterations) {
    // Outside: the iterations taken to escape over the most allowed; inside: 1.
    double a = p.x, b = p.y, a2 = a * a, b2 = b * b;
    for (int i = 0; i < iterations; ++i) {
        b = 2 * a * b + p.y;
        a = a2 - b2 + p.x;
        a2 = a * a;
        b2 = b * b;
        if (a2 + b2 > 4) return static_cast<double>(i) / iterations;
    }
    return 1;
}

} // namespace crt::tracer::patterns
