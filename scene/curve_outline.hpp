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
/// cubic, after) each loop; Bézier segments of four points each.
enum class SplineKind : uint8_t { Linear, Quadratic, Cubic, Bezier };

/// The script's name of each kind, in the enum's order.
inline constexpr std::string_view kSplineKindNames[] = {"linear", "quadratic", "cubic", "bezier"};

/// The fewest points a prism's outline of this kind takes (POV-Ray's).
size_t minimumLoopPoints(SplineKind kind);
/// The fewest points a lathe's profile of this kind takes (POV-Ray's): one segment.
size_t minimumCurvePoints(SplineKind kind);
/// Whether point i of n lies on the curve, rather than only shaping it (the control points
/// before and after the quadratic and cubic splines' segments, a Bézier segment's middle two).
bool isOnCurve(size_t i, size_t n, SplineKind kind);

/// One piece of a curve: p(u) = ((a·u + b)·u + c)·u + d for u in [0, 1].
struct CurveSegment {
    glm::dvec2 a{0.0}, b{0.0}, c{0.0}, d{0.0};
    /// p(1) as written: the sum a + b + c + d rounds, and neighbouring segments must meet.
    glm::dvec2 end{0.0};

    glm::dvec2 at(double u) const { return ((a * u + b) * u + c) * u + d; }
    glm::dvec2 slope(double u) const { return (3.0 * a * u + 2.0 * b) * u + c; }
};

struct CurveLoops {
    std::vector<std::vector<CurveSegment>> loops;
    /// The first point of a loop that never returns to its start (only splines other than
    /// linear, whose last loop is closed by a straight segment as POV-Ray does), or -1.
    std::ptrdiff_t unclosedFrom = -1;
};

/// The loops of POV-Ray's prism points: a loop ends where its first point on the curve comes
/// again (for Bézier, where a segment ends on it), and the next begins after it.
CurveLoops curveLoops(std::span<const glm::dvec2> points, SplineKind kind);

/// The segments of POV-Ray's lathe points, in order: each pair of points for linear, each
/// point after the first but one for quadratic, each but the first and last two for cubic,
/// each four for Bézier (which need not meet). Too few points give none.
std::vector<CurveSegment> curveSegments(std::span<const glm::dvec2> points, SplineKind kind);

/// Whether a lathe's segments, turned about the y axis, bound a solid: each begins where the
/// one before ends, and the last ends where the first begins, or both ends lie on the axis.
bool curveEnclosesSolid(const std::vector<CurveSegment>& segments);

} // namespace crt::scene
