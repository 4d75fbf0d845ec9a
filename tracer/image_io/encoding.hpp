// Transfer functions between linear color values and 8-bit codes (spec §6 "Output"), free of
// OpenImageIO.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace crt::tracer::image_io {

/// The 8-bit code `⌊255 · clamp(c, 0, 1)^(1/gamma) + ½⌋`; NaN counts as 0. `gamma` must be > 0.
std::uint8_t encodeGamma8(float c, double gamma);

/// The 8-bit code of the IEC 61966-2-1 sRGB encoding of `clamp(c, 0, 1)`; NaN counts as 0.
std::uint8_t encodeSrgb8(float c);

/// The sRGB encoding (IEC 61966-2-1) of a linear value, clamped to [0, 1].
float linearToSrgb(float c);

/// The linear value of an sRGB-encoded value in [0, 1] (the inverse of linearToSrgb), for
/// decoding 8-bit images that are read as raw value / 255.
float srgbToLinear(float v);

/// Encodes every value of `values` with encodeSrgb8 when `srgb`, else with encodeGamma8.
std::vector<std::uint8_t> quantise8(std::span<const float> values, double gamma, bool srgb);

} // namespace crt::tracer::image_io
