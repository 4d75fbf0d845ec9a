// Frequency, phase and the waveforms of POV-Ray's documentation.
#include <catch2/catch.hpp>

#include "tracer/patterns/waveform.hpp"

#include <cmath>

using namespace crt;
using tracer::shapeValue;

namespace {

scene::TextureDesc wave(scene::Waveform waveform, double frequency = 1, double phase = 0) {
    scene::TextureDesc d;
    d.waveform = waveform;
    d.frequency = frequency;
    d.phase = phase;
    return d;
}

} // namespace

TEST_CASE("the ramp keeps values in [0, 1] and wraps the others", "[patterns]") {
    auto ramp = wave(scene::Waveform::Ramp);
    for (double v : {0.0, 0.25, 0.5, 0.999}) CHECK(shapeValue(v, ramp) == v);
    CHECK(shapeValue(1.0, ramp) == 1.0); // a pattern's top keeps the map's top
    CHECK(shapeValue(3.0, ramp) == 1.0);
    CHECK(shapeValue(1.25, ramp) == 0.25);
    CHECK(shapeValue(-0.25, ramp) == 0.75);
    CHECK(shapeValue(-1.0, ramp) == 0.0);
    CHECK(shapeValue(0.2, wave(scene::Waveform::Ramp, 3, 0.1)) == Approx(0.7));
    CHECK(shapeValue(0.2, wave(scene::Waveform::Ramp, -1)) == Approx(0.8));
}

TEST_CASE("each waveform has its documented shape", "[patterns]") {
    CHECK(shapeValue(0.25, wave(scene::Waveform::Triangle)) == Approx(0.5));
    CHECK(shapeValue(0.5, wave(scene::Waveform::Triangle)) == Approx(1.0));
    CHECK(shapeValue(0.75, wave(scene::Waveform::Triangle)) == Approx(0.5));
    CHECK(shapeValue(0.25, wave(scene::Waveform::Sine)) == Approx(1.0));
    CHECK(shapeValue(0.75, wave(scene::Waveform::Sine)) == Approx(0.0));
    CHECK(shapeValue(0.5, wave(scene::Waveform::Scallop)) == Approx(1.0));
    CHECK(shapeValue(0.25, wave(scene::Waveform::Scallop)) == Approx(std::sqrt(0.5)));
    CHECK(shapeValue(0.25, wave(scene::Waveform::Cubic)) == Approx(0.15625));
    auto poly = wave(scene::Waveform::Poly);
    poly.exponent = 2.5;
    CHECK(shapeValue(0.5, poly) == Approx(std::pow(0.5, 2.5)));
}
