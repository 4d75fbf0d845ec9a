// Images the renderer reads (panoramas, textures), in linear floats, with bilinear lookup.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <algorithm>
#include <vector>

namespace crt::tracer {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;   ///< row-major, top row first
    std::vector<float> alpha; ///< the same order, one value a pixel; empty when opaque

    Vec3 texel(int x, int y) const {
        const float* p = &rgb[3 * index(x, y)];
        return {p[0], p[1], p[2]};
    }
    /// Bilinear lookup at (u, v) in [0,1]² (v = 0 is the top row); u wraps, v wraps or clamps.
    Vec3 bilinear(double u, double v, bool wrapV) const {
        return interpolate(u, v, wrapV, [&](int x, int y) { return texel(x, y); });
    }
    /// The alpha there, looked up as bilinear() looks up the colour (1 when opaque).
    double bilinearAlpha(double u, double v, bool wrapV) const {
        if (alpha.empty()) return 1;
        return interpolate(u, v, wrapV, [&](int x, int y) { return double(alpha[index(x, y)]); });
    }

  private:
    size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
    template <typename Texel>
    auto interpolate(double u, double v, bool wrapV, Texel&& at) const -> decltype(at(0, 0)) {
        double x = u * width - 0.5, y = v * height - 0.5;
        double fx = std::floor(x), fy = std::floor(y);
        double ax = x - fx, ay = y - fy;
        auto wrap = [](long i, int n) { return static_cast<int>(((i % n) + n) % n); };
        auto row = [&](long j) { return wrapV ? wrap(j, height) : static_cast<int>(std::clamp<long>(j, 0, height - 1)); };
        int x0 = wrap(static_cast<long>(fx), width), x1 = wrap(static_cast<long>(fx) + 1, width);
        int y0 = row(static_cast<long>(fy)), y1 = row(static_cast<long>(fy) + 1);
        return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x1, y0)) +
               ay * ((1 - ax) * at(x0, y1) + ax * at(x1, y1));
    }
};

} // namespace crt::tracer
