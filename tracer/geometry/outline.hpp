// Closed outlines of straight edges in a plane, and which points they enclose.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <vector>

namespace crt::tracer {

/// Closed loops in 2D, read by the even-odd rule: a point is inside where a ray from it
/// crosses the edges an odd number of times, so a loop inside another is a hole (POV-Ray's
/// rule for polygons and prisms).
class Outline {
  public:
    /// Each loop's last point joins its first; loops of fewer than 3 points enclose nothing.
    explicit Outline(const std::vector<std::vector<Vec2>>& loops);

    bool contains(const Vec2& p) const;

  private:
    struct Edge {
        Vec2 a, b;
    };
    std::vector<Edge> edges_;
};

} // namespace crt::tracer
