// The capped solid of revolution behind both the cylinder and the cone primitives.
#include "tracer/geometry/axial_solid.hpp"

namespace crt::tracer {

namespace {

struct Interval {
    double lo = kInfinity;
    double hi = -kInfinity;
    bool empty() const { return !(lo <= hi); }
};

/// Conservative bounds of a disc (centre c, unit normal w, radius r).
Bounds3 discBounds(const Vec3& c, const Vec3& w, double r) {
    Vec3 e = r * glm::sqrt(glm::max(Vec3(1.0) - w * w, Vec3(0.0)));
    return {c - e, c + e};
}

} // namespace

AxialSolid::AxialSolid(const Vec3& base, const Vec3& top, double baseRadius, double topRadius,
                       bool open)
    : base_(base), open_(open) {
    Vec3 axis = top - base;
    height_ = glm::length(axis);
    r0_ = baseRadius > 0 ? baseRadius : 0;
    r1_ = topRadius > 0 ? topRadius : 0;
    empty_ = !(height_ > 0) || !std::isfinite(height_) || !(r0_ > 0 || r1_ > 0);
    frame_ = Frame::fromAxis(empty_ ? Vec3(0, 0, 1) : axis / height_);
    slope_ = empty_ ? 0 : (r1_ - r0_) / height_;
}

Bounds3 AxialSolid::bounds() const {
    if (empty_) return {};
    Bounds3 b = discBounds(base_, frame_.w, r0_);
    b.include(discBounds(base_ + height_ * frame_.w, frame_.w, r1_));
    return padded(b);
}

CRT_FMA_VERSIONS void AxialSolid::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    Vec3 o = frame_.toLocal(ray.origin - base_);
    Vec3 d = frame_.toLocal(ray.dir);
    double dd = glm::dot(d, d);
    if (!(dd > 0)) return;
    // Solve from the line's closest approach to the middle of the axis, so the quadratic's
    // coefficients stay the size of the shape however far away the origin is.
    double tc = -glm::dot(o - Vec3(0, 0, 0.5 * height_), d) / dd;
    o += tc * d;

    // The double cone x² + y² ≤ (r0 + slope·z)² (a cylinder when slope = 0) along the line:
    // a·s² + 2·halfB·s + c ≤ 0.
    double rz = r0_ + slope_ * o.z;
    double sd = slope_ * d.z;
    double a = differenceOfProducts(d.x, d.x, sd, sd) + d.y * d.y;
    double halfB = o.x * d.x + o.y * d.y - rz * sd;
    double c = differenceOfProducts(o.x, o.x, rz, rz) + o.y * o.y;
    double s0 = 0, s1 = 0;
    bool roots = false;
    Interval quadric[2];
    int pieces = 0;
    if (a > 0) {
        roots = solveQuadratic(a, halfB, c, s0, s1);
        if (roots) quadric[pieces++] = {s0, s1};
    } else if (a < 0) {
        // Steeper than the cone's side: inside on both ends of the line (both nappes).
        roots = solveQuadratic(a, halfB, c, s0, s1);
        if (roots) {
            quadric[pieces++] = {-kInfinity, s0};
            quadric[pieces++] = {s1, kInfinity};
        } else {
            quadric[pieces++] = {-kInfinity, kInfinity};
        }
    } else if (halfB != 0) {
        // Parallel to a generatrix: one linear crossing.
        s0 = s1 = -c / (2 * halfB);
        roots = std::isfinite(s0);
        if (roots)
            quadric[pieces++] = halfB > 0 ? Interval{-kInfinity, s0} : Interval{s0, kInfinity};
    } else if (c <= 0) {
        quadric[pieces++] = {-kInfinity, kInfinity};
    }

    if (open_) {
        if (!roots) return;
        // The surface only: the quadric's roots within the height (the other nappe lies
        // beyond the apex, outside the height).
        double candidates[2] = {s0, s1};
        int n = a == 0 ? 1 : 2;
        for (int i = 0; i < n; ++i) {
            double z = o.z + candidates[i] * d.z;
            if (z >= 0 && z <= height_) out.add(tc + candidates[i], 0);
        }
        return;
    }

    // The slab 0 ≤ z ≤ height; the caps are parts 1 (base) and 2 (top).
    Interval slab{-kInfinity, kInfinity};
    uint32_t slabLoPart = 1, slabHiPart = 2;
    if (d.z != 0) {
        double tb = -o.z / d.z, tt = (height_ - o.z) / d.z;
        if (d.z > 0) {
            slab = {tb, tt};
        } else {
            slab = {tt, tb};
            slabLoPart = 2;
            slabHiPart = 1;
        }
    } else if (o.z < 0 || o.z > height_) {
        return;
    }
    // The frustum is convex, so at most one piece survives the clip (rounding near an apex on
    // a cap can leave a sliver of the other: keep the longer one).
    Interval best;
    uint32_t loPart = 0, hiPart = 0;
    for (int i = 0; i < pieces; ++i) {
        Interval clip{std::max(quadric[i].lo, slab.lo), std::min(quadric[i].hi, slab.hi)};
        if (clip.empty() || (!best.empty() && clip.hi - clip.lo <= best.hi - best.lo)) continue;
        best = clip;
        loPart = quadric[i].lo >= slab.lo ? 0 : slabLoPart;
        hiPart = quadric[i].hi <= slab.hi ? 0 : slabHiPart;
    }
    if (best.empty() || !std::isfinite(best.lo) || !std::isfinite(best.hi)) return;
    out.add(tc + best.lo, loPart);
    out.add(tc + best.hi, hiPart);
}

SurfacePoint AxialSolid::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    Vec3 p = ray.at(crossing.t);
    Vec3 q = frame_.toLocal(p - base_);
    double rho = std::sqrt(q.x * q.x + q.y * q.y);
    double angle = wantUv ? angleCoordinate(q.y, q.x) : 0.0;
    // Local coordinates round a few times relative to |p| + |base|, and the frame's axis is
    // off by a few roundings, which moves points by that much times their distance from base.
    double scale = sumAbs(p) + sumAbs(base_) + std::max(r0_, r1_);
    double distanceError = errorGamma(16) * scale;
    Vec3 n;
    double distance;
    SurfacePoint sp;
    double cx = rho > 0 ? q.x / rho : 1, cy = rho > 0 ? q.y / rho : 0;
    // Every part turns with u: the point moves by 2π·ρ per unit of u, around the axis.
    if (wantUv) sp.dpdu = frame_.fromLocal(2 * kPi * Vec3(-q.y, q.x, 0));
    if (crossing.part == 1 || crossing.part == 2) {
        bool top = crossing.part == 2;
        n = top ? frame_.w : -frame_.w;
        distance = top ? q.z - height_ : -q.z;
        double capRadius = top ? r1_ : r0_;
        if (wantUv) {
            sp.uv = {angle, capRadius > 0 ? clamp01(rho / capRadius) : 0.0};
            sp.dpdv = frame_.fromLocal(capRadius * Vec3(cx, cy, 0));
        }
    } else {
        // Outward normal of x² + y² = (r0 + slope·z)²: (x/ρ, y/ρ, −slope) normalised; the
        // distance to the side along it is (ρ − r(z)) / √(1 + slope²).
        double norm = std::sqrt(1 + slope_ * slope_);
        n = frame_.fromLocal(Vec3(cx, cy, -slope_) / norm);
        distance = (rho - (r0_ + slope_ * q.z)) / norm;
        if (wantUv) {
            sp.uv = {angle, clamp01(q.z / height_)};
            // Up the side at a fixed angle, the radius grows by the slope.
            sp.dpdv = frame_.fromLocal(height_ * Vec3(slope_ * cx, slope_ * cy, 1));
        }
    }
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    return sp;
}

} // namespace crt::tracer
