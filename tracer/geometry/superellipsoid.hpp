// The superellipsoid primitive: POV-Ray's, found along the line by bracketed Newton steps.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

namespace crt::tracer {

/// The solid (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) ≤ 1, inside the cube [-1, 1]³: e
/// rounds the sections across z, n the profile along it. e = n = 1 is the unit sphere; toward
/// 0 the cube; above 2 the faces curve inward to a star. UV: u = angle around z
/// (counter-clockwise from +x), v = latitude from −z (0) to +z (1), as seen from the centre.
class SuperellipsoidGeometry {
  public:
    /// Exponents at or below zero, or not finite, give no crossings at all.
    explicit SuperellipsoidGeometry(const scene::SuperellipsoidShape& desc);

    Bounds3 bounds() const;
    /// Every crossing, ascending; a tangency gives none or two.
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return true; }
    /// With e and n at most 2 the solid is convex: a line crosses it at most twice.
    bool convex() const { return !empty_ && sectionPower_ >= 1 && profilePower_ >= 1; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 0, 1)}; }

  private:
    /// The superellipsoid's "radius" of p: 1 on the surface, below inside, homogeneous of
    /// degree 1 (twice as far out, twice the value), with its gradient.
    struct Radius {
        double value;
        Vec3 gradient;
    };
    Radius radiusAt(const Vec3& p) const;
    /// The radius minus 1 at base + s·dir, and its slope along dir.
    ValueAndSlope alongLine(const Vec3& base, const Vec3& dir, double s) const;
    /// Appends the crossings of q(s) = base + s·dir (dir of unit length) for s in [lo, hi],
    /// where the radius minus 1 is smooth, given its value and slope at both ends.
    void crossPiece(const Vec3& base, const Vec3& dir, double lo, double hi, ValueAndSlope atLo,
                    ValueAndSlope atHi, double toT, double tStart, CrossingList& out) const;

    double sectionPower_ = 2; ///< 2 / e
    double profilePower_ = 2; ///< 2 / n
    bool empty_ = true;
};

} // namespace crt::tracer
