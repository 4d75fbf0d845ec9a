// The superellipsoid primitive: POV-Ray's, found along the line by bracketed Newton steps.
#include "tracer/geometry/superellipsoid.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

/// (a^k + b^k)^(1/k) for a, b ≥ 0, from the larger one so that no power overflows or
/// underflows to nothing whatever k (POV-Ray evaluates it the same way).
double powerSum(double a, double b, double k) {
    double hi = std::max(a, b), lo = std::min(a, b);
    if (hi == 0) return 0;
    return hi * std::pow(1 + std::pow(lo / hi, k), 1 / k);
}

/// ∂/∂a of powerSum(a, b, k) = (a / sum)^(k − 1). Infinite at a cusp (k < 1, a = 0), where
/// the normal is the limit along the other axis; capped so that normalising stays finite.
double powerSumSlope(double a, double sum, double k) {
    if (!(sum > 0)) return 0;
    return std::min(std::pow(a / sum, k - 1), 1e100);
}

/// Half the side of the cube the line is clipped to: outside the solid by a margin far above
/// the rounding of the clipped ends, so both ends are outside (the radius is at least the
/// largest coordinate) and every crossing is a change of sign.
constexpr double kReach = 1 + 1e-6;
/// Pieces of a line through a star-shaped (non-convex) superellipsoid are split this many
/// times again, so that each holds at most one dip of the radius.
constexpr int kStarSubdivisions = 4;

/// Where the line base + s·dir meets the box [-kReach, kReach]³: false when it misses.
bool clipToCube(const Vec3& origin, const Vec3& dir, double& tEnter, double& tLeave) {
    tEnter = -kInfinity;
    tLeave = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) {
            if (std::abs(origin[axis]) > kReach) return false;
            continue;
        }
        double t0 = (-kReach - origin[axis]) / dir[axis], t1 = (kReach - origin[axis]) / dir[axis];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tLeave = std::min(tLeave, t1);
    }
    return tEnter < tLeave;
}

} // namespace

SuperellipsoidGeometry::SuperellipsoidGeometry(const scene::SuperellipsoidShape& desc) {
    empty_ = !(desc.e > 0 && desc.n > 0 && std::isfinite(desc.e) && std::isfinite(desc.n));
    if (!empty_) {
        sectionPower_ = 2 / desc.e;
        profilePower_ = 2 / desc.n;
    }
}

Bounds3 SuperellipsoidGeometry::bounds() const {
    if (empty_) return {};
    return padded({Vec3(-1.0), Vec3(1.0)});
}

SuperellipsoidGeometry::Radius SuperellipsoidGeometry::radiusAt(const Vec3& p) const {
    const Vec3 a = absolute(p);
    const double section = powerSum(a.x, a.y, sectionPower_);
    const double radius = powerSum(section, a.z, profilePower_);
    const double bySection = powerSumSlope(section, radius, profilePower_);
    const Vec3 slopes(bySection * powerSumSlope(a.x, section, sectionPower_),
                      bySection * powerSumSlope(a.y, section, sectionPower_),
                      powerSumSlope(a.z, radius, profilePower_));
    return {radius, Vec3(std::copysign(slopes.x, p.x), std::copysign(slopes.y, p.y),
                         std::copysign(slopes.z, p.z))};
}

ValueAndSlope SuperellipsoidGeometry::alongLine(const Vec3& base, const Vec3& dir, double s) const {
    const Radius r = radiusAt(base + s * dir);
    return {r.value - 1, glm::dot(r.gradient, dir)};
}

void SuperellipsoidGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    const double dirLength = glm::length(ray.dir);
    double tEnter, tLeave;
    if (!(dirLength > 0) || !clipToCube(ray.origin, ray.dir, tEnter, tLeave)) return;
    // Along a unit direction from where the line enters the cube: s is then in object units,
    // of order 1, as the root finder's absolute tolerance wants.
    const Vec3 base = ray.at(tEnter);
    const Vec3 dir = ray.dir / dirLength;
    const double length = (tLeave - tEnter) * dirLength;

    // The radius is smooth but where a coordinate is zero. A convex solid's radius is a convex
    // function along the line: one piece holds everything. A star's is split where POV-Ray
    // splits it (the coordinate planes and the diagonal ones), and each piece again.
    double points[2 + 9 * (kStarSubdivisions + 1) + kStarSubdivisions];
    int count = 0;
    points[count++] = 0;
    if (!convex()) {
        constexpr double kPlanes[9][3] = {{1, 0, 0}, {0, 1, 0},  {0, 0, 1}, {1, 1, 0}, {1, -1, 0},
                                          {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}};
        for (const auto& plane : kPlanes) {
            const Vec3 normal(plane[0], plane[1], plane[2]);
            const double along = glm::dot(normal, dir);
            const double s = along != 0 ? -glm::dot(normal, base) / along : -1;
            if (s > 0 && s < length) points[count++] = s;
        }
        std::sort(points + 1, points + count);
    }
    points[count++] = length;
    if (!convex()) {
        // Subdivide each piece, from the last so that the array can be rewritten in place.
        const int pieces = count - 1;
        int written = pieces * kStarSubdivisions + 1;
        for (int i = pieces; i > 0; --i) {
            const double lo = points[i - 1], hi = points[i];
            for (int k = kStarSubdivisions; k > 0; --k)
                points[--written] = lo + (hi - lo) * k / kStarSubdivisions;
        }
        count = pieces * kStarSubdivisions + 1;
    }

    auto at = [&](double s) { return alongLine(base, dir, s); };
    const double toT = 1 / dirLength;
    ValueAndSlope previous = at(points[0]);
    for (int i = 1; i < count; ++i) {
        const ValueAndSlope next = at(points[i]);
        crossPiece(base, dir, points[i - 1], points[i], previous, next, toT, tEnter, out);
        previous = next;
    }
}

void SuperellipsoidGeometry::crossPiece(const Vec3& base, const Vec3& dir, double lo, double hi,
                                        ValueAndSlope atLo, ValueAndSlope atHi, double toT,
                                        double tStart, CrossingList& out) const {
    auto at = [&](double s) { return alongLine(base, dir, s); };
    auto add = [&](double s) { out.add(tStart + s * toT, 0); };
    if ((atLo.value < 0) != (atHi.value < 0)) {
        add(bracketedRoot(at, lo, hi, atLo.value < 0));
        return;
    }
    // Outside at both ends: the line may still dip inside where the radius falls then rises.
    if (atLo.value < 0 || !(atLo.slope < 0 && atHi.slope > 0)) return;
    constexpr double kTolerance = 0x1p-48;
    for (int i = 0; i < 64 && hi - lo > kTolerance; ++i) {
        // The tangents at both ends bound a convex radius from below where they meet: above 1
        // there, the line stays outside.
        const double meet = (atHi.value - atLo.value + atLo.slope * lo - atHi.slope * hi) /
                            (atLo.slope - atHi.slope);
        if (atLo.value + atLo.slope * (meet - lo) >= 0) return;
        // Toward the minimum: where the slope's secant is zero, kept off the ends so that the
        // interval shrinks by an eighth at least.
        const double width = hi - lo;
        const double guess = lo - atLo.slope * width / (atHi.slope - atLo.slope);
        const double s = std::clamp(guess, lo + width / 8, hi - width / 8);
        const ValueAndSlope mid = at(s);
        if (mid.value < 0) {
            add(bracketedRoot(at, lo, s, false));
            add(bracketedRoot(at, s, hi, true));
            return;
        }
        if (mid.slope < 0) {
            lo = s;
            atLo = mid;
        } else {
            hi = s;
            atHi = mid;
        }
    }
}

SurfacePoint SuperellipsoidGeometry::surfaceAt(const Ray& ray, const Crossing& crossing,
                                               bool wantUv) const {
    const Vec3 p = ray.at(crossing.t);
    const Radius r = radiusAt(p);
    const double slope = glm::length(r.gradient);
    const bool usable = slope > 0 && std::isfinite(slope);
    const Vec3 n = usable ? r.gradient / slope : glm::normalize(p);
    // The radius is homogeneous of degree 1, so its slope across the surface is at least
    // 1/√3 there: the radius's error over it bounds the distance's. Each power rounds a few
    // times relative to the radius (about 1), and the powers amplify nothing: the large
    // exponent of a box-like shape is undone by its inverse.
    const double distance = usable ? (r.value - 1) / slope : 0;
    const double distanceError = errorGamma(32) * (r.value + 1) / (usable ? slope : 1);
    const RefinedPoint refined = refineOntoSurface(p, distance, distanceError, n);
    SurfacePoint sp;
    sp.point = refined.point;
    sp.pointError = refined.error;
    sp.normal = n;
    sp.shadingNormal = n;
    if (wantUv) {
        const double len = glm::length(p);
        sp.uv = {angleCoordinate(p.y, p.x),
                 clamp01(0.5 + std::asin(std::clamp(len > 0 ? p.z / len : 0.0, -1.0, 1.0)) / kPi)};
    }
    return sp;
}

} // namespace crt::tracer
