// A Function as a pattern (POV-Ray's function pattern).
#include "tracer/patterns/pattern_functions.hpp"

#include <cmath>

namespace crt::tracer::patterns {

double function(const Vec3& p, const scene::FunctionProgram& f) {
    // POV-Ray keeps the fraction of a value above 1 before its frequency and phase, so that 2
    // reads as 0 where the waveform's wrap alone would give 1.
    const double v = f.at(p.x, p.y, p.z);
    return v > 1 ? std::fmod(v, 1.0) : v;
}

} // namespace crt::tracer::patterns
