// Waveforms as POV-Ray 3.7 defines them (its documentation, "Waveforms").
#include "tracer/patterns/waveform.hpp"

#include "tracer/geometry/ray.hpp"

#include <cmath>

namespace crt::tracer {

namespace {

double wrapped(double value) {
    double whole = std::floor(value);
    if (value == whole && value > 0) return 1;
    return value - whole;
}

double cycloidal(double value) {
    return std::sin(2 * kPi * value);
}

} // namespace

double triangleWave(double value) {
    double offset = fract(value);
    return offset >= 0.5 ? 2 * (1 - offset) : 2 * offset;
}

double shapeValue(double value, const scene::TextureDesc& desc) {
    double v = wrapped(value * desc.frequency + desc.phase);
    switch (desc.waveform) {
    case scene::Waveform::Ramp: return v;
    case scene::Waveform::Triangle: return triangleWave(v);
    case scene::Waveform::Sine: return (1 + cycloidal(v)) * 0.5;
    case scene::Waveform::Scallop: return std::abs(cycloidal(v * 0.5));
    case scene::Waveform::Cubic: return v * v * (3 - 2 * v);
    case scene::Waveform::Poly: return std::pow(v, desc.exponent);
    }
    return v;
}

} // namespace crt::tracer
