// Curves as POV-Ray's prism and lathe read their points: a prism's closed loops and a
// lathe's profile, of curve segments one cubic polynomial each. Shared by the front end
// (which checks the points) and the renderer.
#pragma once

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace crt::scene {

/// How points make a curve, as POV-Ray's prism and lathe read them: straight lines;
/// quadratic and cubic (Catmull-Rom) splines through all but a control point before (and for
/// cubic, after) each loop; Bézier segments of four points each; and the uniform cubic
/// B-spline (POV-Ray's sphere_sweep b_spline), which passes near its points, not through.
enum class SplineKind : uint8_t { Linear, Quadratic, Cubic, Bezier, BSpline };

/// The script's name of each kind, in the enum's order.
inline constexpr std::string_view kSplineKindNames[] = {"linear", "quadratic", "cubic", "bezier",
                                                        "bspline"};
/// The kinds a prism's loops take: all but the B-spline, which has no point to close a loop at.
inline constexpr std::span<const std::string_view> kLoopSplineKindNames(kSplineKindNames, 4);
/// The kinds POV-Ray's sphere_sweep takes.
inline constexpr std::string_view kSweepSplineKindNames[] = {"linear", "cubic", "bspline"};

/// The fewest points a prism's outline of this kind takes (POV-Ray's).
size_t minimumLoopPoints(SplineKind kind);
/// The fewest points a lathe's profile of this kind takes (POV-Ray's): one segment.
size_t minimumCurvePoints(SplineKind kind);
/// Whether point i of n lies on the curve, rather than only shaping it (the control points
/// before and after the quadratic and cubic splines' segments, a Bézier segment's middle two).
bool isOnCurve(size_t i, size_t n, SplineKind kind);

/// One piece of a curve: p(u) = ((a·u + b)·u + c)·u + d for u in [0, 1], in 2D (prisms,
/// lathes) or 3D (a script's Spline).
template <class V> struct CurveSegmentOf {
    V a{0.0}, b{0.0}, c{0.0}, d{0.0};
    /// p(1) as written: the sum a + b + c + d rounds, and neighbouring segments must meet.
    V end{0.0};

    V at(double u) const { return ((a * u + b) * u + c) * u + d; }
    V slope(double u) const { return (3.0 * a * u + 2.0 * b) * u + c; }
};
using CurveSegment = CurveSegmentOf<glm::dvec2>;

namespace curve_pieces {

template <class V> CurveSegmentOf<V> line(const V& p0, const V& p1) {
    return {V(0.0), V(0.0), p1 - p0, p0, p1};
}
/// Through p1 and p2, with p0 setting the slope at p1 (POV-Ray's quadratic spline).
template <class V> CurveSegmentOf<V> quadratic(const V& p0, const V& p1, const V& p2) {
    return {V(0.0), 0.5 * p0 - p1 + 0.5 * p2, -0.5 * p0 + 0.5 * p2, p1, p2};
}
/// From p1 to p2, with slopes from p0 and p3 (Catmull-Rom).
template <class V> CurveSegmentOf<V> cubic(const V& p0, const V& p1, const V& p2, const V& p3) {
    return {-0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3, p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3,
            -0.5 * p0 + 0.5 * p2, p1, p2};
}
template <class V> CurveSegmentOf<V> bezier(const V& p0, const V& p1, const V& p2, const V& p3) {
    return {p3 - 3.0 * p2 + 3.0 * p1 - p0, 3.0 * p2 - 6.0 * p1 + 3.0 * p0, 3.0 * p1 - 3.0 * p0, p0,
            p3};
}
/// The uniform cubic B-spline's piece over p0 … p3: from (p0 + 4·p1 + p2) / 6 to
/// (p1 + 4·p2 + p3) / 6.
template <class V> CurveSegmentOf<V> bspline(const V& p0, const V& p1, const V& p2, const V& p3) {
    return {(-p0 + 3.0 * p1 - 3.0 * p2 + p3) / 6.0, (3.0 * p0 - 6.0 * p1 + 3.0 * p2) / 6.0,
            (p2 - p0) / 2.0, (p0 + 4.0 * p1 + p2) / 6.0, (p1 + 4.0 * p2 + p3) / 6.0};
}

} // namespace curve_pieces

/// The segments of POV-Ray's lathe points, in order: each pair of points for linear, each
/// point after the first but one for quadratic, each but the first and last two for cubic
/// (and for the B-spline), each four for Bézier (which need not meet). Too few points give
/// none.
template <class V>
std::vector<CurveSegmentOf<V>> curveSegmentsOf(std::span<const V> p, SplineKind kind) {
    using namespace curve_pieces;
    std::vector<CurveSegmentOf<V>> out;
    const size_t n = p.size();
    switch (kind) {
    case SplineKind::Linear:
        for (size_t i = 0; i + 1 < n; ++i) out.push_back(line(p[i], p[i + 1]));
        break;
    case SplineKind::Quadratic:
        for (size_t i = 0; i + 2 < n; ++i) out.push_back(quadratic(p[i], p[i + 1], p[i + 2]));
        break;
    case SplineKind::Cubic:
        for (size_t i = 0; i + 3 < n; ++i) out.push_back(cubic(p[i], p[i + 1], p[i + 2], p[i + 3]));
        break;
    case SplineKind::Bezier:
        for (size_t i = 0; i + 3 < n; i += 4)
            out.push_back(bezier(p[i], p[i + 1], p[i + 2], p[i + 3]));
        break;
    case SplineKind::BSpline:
        for (size_t i = 0; i + 3 < n; ++i)
            out.push_back(bspline(p[i], p[i + 1], p[i + 2], p[i + 3]));
        break;
    }
    return out;
}

struct CurveLoops {
    std::vector<std::vector<CurveSegment>> loops;
    /// The first point of a loop that never returns to its start (only splines other than
    /// linear, whose last loop is closed by a straight segment as POV-Ray does), or -1.
    std::ptrdiff_t unclosedFrom = -1;
};

/// The loops of POV-Ray's prism points: a loop ends where its first point on the curve comes
/// again (for Bézier, where a segment ends on it), and the next begins after it.
CurveLoops curveLoops(std::span<const glm::dvec2> points, SplineKind kind);

/// curveSegmentsOf for a lathe's points.
inline std::vector<CurveSegment> curveSegments(std::span<const glm::dvec2> points,
                                               SplineKind kind) {
    return curveSegmentsOf(points, kind);
}

/// Whether a lathe's segments, turned about the y axis, bound a solid: each begins where the
/// one before ends, and the last ends where the first begins, or both ends lie on the axis.
bool curveEnclosesSolid(const std::vector<CurveSegment>& segments);

} // namespace crt::scene
