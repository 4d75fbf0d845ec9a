// The buffers a path-traced render can write beside its image (arbitrary output variables,
// `--aov`): each pixel's variance, and the albedo and normal of what its paths first meet,
// the inputs a denoiser takes.
#pragma once

#include <array>
#include <bit>
#include <string_view>

namespace crt::tracer {

enum class Aov { Variance, Albedo, Normal };
inline constexpr std::array<std::string_view, 3> kAovNames{"variance", "albedo", "normal"};

/// Three floats a pixel each, after the image's own channels, in the order of Aov whatever the
/// order they were asked for in.
struct AovSet {
    unsigned bits = 0;

    bool has(Aov a) const { return (bits >> static_cast<unsigned>(a)) & 1u; }
    void add(Aov a) { bits |= 1u << static_cast<unsigned>(a); }
    bool empty() const { return bits == 0; }
    int channels() const { return 3 * std::popcount(bits); }
    bool operator==(const AovSet&) const = default;
};

/// The floats a pixel of a tile: RGB, alpha with `alpha`, then the AOVs.
inline int tileChannels(bool alpha, AovSet aovs) { return (alpha ? 4 : 3) + aovs.channels(); }

} // namespace crt::tracer
