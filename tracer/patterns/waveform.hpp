// What a pattern's value goes through before its map reads it: frequency, phase, waveform.
#pragma once

#include "scene/scene_desc.hpp"

namespace crt::tracer {

/// frac(value · frequency + phase), where a positive whole number stays 1 (so that a
/// pattern's highest value keeps the top of its map), then shaped by the waveform.
double shapeValue(double value, const scene::TextureDesc& desc);

/// 0 → 1 → 0 over each unit: POV-Ray's triangle wave (Spiral's waveform, Wood's rings).
double triangleWave(double value);

} // namespace crt::tracer
