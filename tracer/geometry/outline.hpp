// Closed outlines in a plane, of straight edges or curve segments, and which points they
// enclose.
#pragma once

#include "scene/curve_outline.hpp"
#include "tracer/geometry/ray.hpp"

#include <vector>

namespace crt::tracer {

/// Closed loops in 2D, read by the even-odd rule: a point is inside where a ray from it
/// crosses the edges an odd number of times, so a loop inside another is a hole (POV-Ray's
/// rule for polygons and prisms).
class Outline {
  public:
    /// Straight edges: each loop's last point joins its first; loops of fewer than 3 points
    /// enclose nothing.
    explicit Outline(const std::vector<std::vector<Vec2>>& loops);
    /// Curve segments, each loop closed (scene::curveLoops).
    explicit Outline(const std::vector<std::vector<scene::CurveSegment>>& loops);

    bool contains(const Vec2& p) const;

  private:
    struct Edge {
        Vec2 a, b;
    };
    /// A piece of a curve segment along which y only rises or only falls, from a = p(u0)
    /// to b = p(u1).
    struct Arc {
        scene::CurveSegment curve;
        double u0, u1;
        Vec2 a, b;
    };
    void addCurve(const scene::CurveSegment& s);
    /// The x where the arc reaches height y, strictly between its ends' heights.
    static double crossingX(const Arc& arc, double y);

    std::vector<Edge> edges_;
    std::vector<Arc> arcs_;
};

} // namespace crt::tracer
