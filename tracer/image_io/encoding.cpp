// Transfer functions between linear color values and 8-bit codes.
#include "tracer/image_io/encoding.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace crt::tracer::image_io {
namespace {

// Written so that NaN fails the first comparison and becomes 0, as the spec's clamp intends
// (a NaN sample must not turn into an arbitrary code through an undefined float-to-int cast).
double clamp01(float c) {
    if (!(c > 0.0f)) return 0.0;
    if (c >= 1.0f) return 1.0;
    return c;
}

// `encoded` is in [0, 1], so truncation is the floor (and avoids a libm call per value).
std::uint8_t toCode(double encoded) {
    return static_cast<std::uint8_t>(255.0 * encoded + 0.5);
}

// In double precision so that the codes are exactly those of the spec's formula, not of a
// float approximation that could land on the other side of a rounding boundary.
double srgbEncode(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

} // namespace

std::uint8_t encodeGamma8(float c, double gamma) {
    const double x = clamp01(c);
    return toCode(gamma == 1.0 ? x : std::pow(x, 1.0 / gamma));
}

std::uint8_t encodeSrgb8(float c) {
    return toCode(srgbEncode(clamp01(c)));
}

float linearToSrgb(float c) {
    return static_cast<float>(srgbEncode(clamp01(c)));
}

float srgbToLinear(float v) {
    const double x = clamp01(v);
    return static_cast<float>(x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4));
}

namespace {

// A pow per value would cost more than compressing the image, so whole images go through
// tables instead. lower[k] is the smallest float whose exact code is at least k;
// since the exact code is monotone in the value, the largest k with lower[k] <= c is exactly
// that code. To avoid searching all of lower[] per value, start[] holds the code at the start
// of each bucket of float bit patterns (2^14 patterns, 0.2 % of the value, about a quarter of a
// code), leaving a step or two. Building both is cheap next to a pow per value of an image.
class CodeTable {
  public:
    template <class Encode> explicit CodeTable(Encode encode) : start_(kBuckets) {
        lower_[0] = 0.0f;
        for (int k = 1; k < 256; ++k) {
            // Non-negative floats order like their bit patterns; encode(1) == 255 >= k.
            std::uint32_t lo = 0, hi = kOne;
            while (lo < hi) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                if (encode(std::bit_cast<float>(mid)) >= k)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            lower_[k] = std::bit_cast<float>(lo);
        }
        lower_[256] = std::numeric_limits<float>::infinity(); // the scan below stops here
        unsigned k = 0;
        for (std::uint32_t b = 0; b < kBuckets; ++b) {
            const float first = std::bit_cast<float>(b << kShift);
            while (lower_[k + 1] <= first) ++k;
            start_[b] = std::uint8_t(k);
        }
    }

    std::uint8_t operator()(float c) const {
        if (!(c > 0.0f)) return 0;
        if (c >= 1.0f) return 255;
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(c);
        unsigned k = start_[bits >> kShift];
        while (lower_[k + 1] <= c) ++k;
        return std::uint8_t(k);
    }

  private:
    static constexpr std::uint32_t kOne = 0x3f800000u; // the bits of 1.0f
    static constexpr unsigned kShift = 14;
    static constexpr std::uint32_t kBuckets = kOne >> kShift;

    std::array<float, 257> lower_;
    std::vector<std::uint8_t> start_;
};

} // namespace

std::vector<std::uint8_t> quantise8(std::span<const float> values, double gamma, bool srgb) {
    std::vector<std::uint8_t> codes(values.size());
    if (!srgb && gamma == 1.0) {
        for (std::size_t i = 0; i < values.size(); ++i) codes[i] = encodeGamma8(values[i], 1.0);
        return codes;
    }
    const CodeTable table =
        srgb ? CodeTable([](float c) { return int(encodeSrgb8(c)); })
             : CodeTable([gamma](float c) { return int(encodeGamma8(c, gamma)); });
    for (std::size_t i = 0; i < values.size(); ++i) codes[i] = table(values[i]);
    return codes;
}

} // namespace crt::tracer::image_io
