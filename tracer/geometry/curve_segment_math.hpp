// Measures of the curve segments that prisms and lathes are made of (scene/curve_outline.hpp).
#pragma once

#include "scene/curve_outline.hpp"
#include "tracer/geometry/geometry_math.hpp"

#include <vector>

namespace crt::tracer {

/// ∮ x dy along the segments, the curve's second coordinate being y: the area they enclose,
/// positive when they run counter-clockwise. Pieces along the line x = 0 add nothing, so a
/// curve from that line back to it may leave them out.
inline double signedArea(const std::vector<scene::CurveSegment>& segments) {
    double area = 0;
    for (const scene::CurveSegment& s : segments) {
        // ∫₀¹ x(u)·y'(u) du, term by term: xᵢ uⁱ · y'ⱼ uʲ integrates to xᵢ y'ⱼ / (i + j + 1).
        const double x[4] = {s.d.x, s.c.x, s.b.x, s.a.x};
        const double dy[3] = {s.c.y, 2 * s.b.y, 3 * s.a.y};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) area += x[i] * dy[j] / (i + j + 1);
    }
    return area;
}

/// Widens [lo, hi] to hold the segment: its ends and where either coordinate turns.
inline void includeSegment(const scene::CurveSegment& s, Vec2& lo, Vec2& hi) {
    auto include = [&](const Vec2& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    include(s.d);
    include(s.end);
    for (int k = 0; k < 2; ++k) {
        double r[2];
        if (solveQuadratic(3 * s.a[k], s.b[k], s.c[k], r[0], r[1])) {
            for (double u : r)
                if (u > 0 && u < 1) include(s.at(u));
        } else if (s.a[k] == 0 && s.b[k] != 0) {
            const double u = -s.c[k] / (2 * s.b[k]);
            if (u > 0 && u < 1) include(s.at(u));
        }
    }
}

} // namespace crt::tracer
