// The torus primitive: a quartic solved robustly in double precision.
#include "tracer/geometry/torus.hpp"

namespace crt::tracer {

TorusGeometry::TorusGeometry(const scene::TorusShape& desc) : center_(desc.center) {
    double len = glm::length(desc.axis);
    major_ = desc.major > 0 ? desc.major : 0;
    minor_ = desc.minor > 0 ? desc.minor : 0;
    empty_ = !(major_ > 0 && minor_ > 0) || !(len > 0) || !std::isfinite(len);
    frame_ = Frame::fromAxis(empty_ ? Vec3(0, 1, 0) : desc.axis / len);
}

Bounds3 TorusGeometry::bounds() const {
    if (empty_) return {};
    const Vec3& w = frame_.w;
    Vec3 e = major_ * glm::sqrt(glm::max(Vec3(1.0) - w * w, Vec3(0.0))) + Vec3(minor_);
    return padded({center_ - e, center_ + e});
}

void TorusGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (empty_) return;
    Vec3 o = frame_.toLocal(ray.origin - center_);
    Vec3 d = frame_.toLocal(ray.dir);
    double dd = glm::dot(d, d);
    if (!(dd > 0)) return;
    // Solve around the line's closest approach to the centre, in units of the bounding
    // sphere's radius, along a unit direction: the quartic's coefficients are then of order 1
    // whatever the origin, so a far origin costs only the rounding of that point.
    double tc = -glm::dot(o, d) / dd;
    double scale = 1 / (major_ + minor_);
    Vec3 p = (o + tc * d) * scale;
    if (!(glm::dot(p, p) <= 1)) return; // misses the bounding sphere
    double dlen = std::sqrt(dd);
    Vec3 e = d / dlen;
    double R = major_ * scale, r = minor_ * scale;

    // F(s) = (|q|² + R² − r²)² − 4R²(qx² + qy²) at q = p + s·e is the quartic c4·s⁴ + … + c0;
    // only its derivatives are needed, to split the line where F is monotone.
    double ee = glm::dot(e, e), m = glm::dot(p, e);
    double k = glm::dot(p, p) + (R - r) * (R + r);
    double exy = e.x * e.x + e.y * e.y, mxy = p.x * e.x + p.y * e.y;
    double c4 = ee * ee, c3 = 4 * ee * m;
    double c2 = 4 * m * m + 2 * ee * k - 4 * R * R * exy;
    double c1 = 4 * m * k - 8 * R * R * mxy;
    auto dF = [&](double s) { return ((4 * c4 * s + 3 * c3) * s + 2 * c2) * s + c1; };
    auto ddF = [&](double s) { return (12 * c4 * s + 6 * c3) * s + 2 * c2; };
    // The crossings are the sign changes of f1 = (ρ − R)² + z² − r², negative inside the tube
    // and evaluated from the point: far more accurate near the surface than the expanded
    // quartic. F = f1·f2 with f2 = (ρ + R)² + z² − r² (which also vanishes on the inner lemon of
    // a spindle torus, minor > major, where it bounds nothing), so f1's roots are among F's.
    auto tube = [&](double s) {
        Vec3 q = p + s * e;
        double rho = std::sqrt(q.x * q.x + q.y * q.y);
        return (rho - R) * (rho - R) + (q.z - r) * (q.z + r);
    };
    auto dTube = [&](double s) {
        Vec3 q = p + s * e;
        double rho = std::sqrt(q.x * q.x + q.y * q.y);
        double dRho = rho > 0 ? (q.x * e.x + q.y * e.y) / rho : 0;
        return 2 * (rho - R) * dRho + 2 * q.z * e.z;
    };

    // Beyond |s| = L the point is outside the bounding sphere, where F > 0.
    constexpr double L = 1.0625;
    // The quartic's critical points (roots of F', found between the roots of F'') split
    // [−L, L] into pieces where F is monotone, so each holds at most one root of F, hence of
    // f1: exactly when f1 differs in sign at its ends. Each end's sign is evaluated once and
    // both outer ends are outside, so the crossings alternate and are even by construction;
    // a tangency (a double root) changes no sign and gives none.
    double split[4];
    int nSplit = 0;
    split[nSplit++] = -L;
    double q0, q1;
    if (solveQuadratic(12 * c4, 3 * c3, 2 * c2, q0, q1)) {
        if (q0 > -L && q0 < L) split[nSplit++] = q0;
        if (q1 > q0 && q1 > -L && q1 < L) split[nSplit++] = q1;
    }
    split[nSplit++] = L;
    double points[5];
    int nPoints = 0;
    points[nPoints++] = -L;
    for (int i = 0; i + 1 < nSplit; ++i) {
        double fa = dF(split[i]), fb = dF(split[i + 1]);
        if ((fa < 0) != (fb < 0))
            points[nPoints++] = bracketedRoot(
                [&](double s) {
                    return ValueAndSlope{dF(s), ddF(s)};
                },
                split[i], split[i + 1], fa < 0);
    }
    points[nPoints++] = L;

    double toT = (major_ + minor_) / dlen;
    bool insideBefore = false;
    for (int i = 0; i + 1 < nPoints; ++i) {
        bool insideAfter = i + 2 < nPoints && tube(points[i + 1]) < 0;
        if (insideBefore != insideAfter)
            out.add(tc + bracketedRoot(
                             [&](double s) {
                                 return ValueAndSlope{tube(s), dTube(s)};
                             },
                             points[i], points[i + 1], insideBefore) *
                             toT,
                    0);
        insideBefore = insideAfter;
    }
}

SurfacePoint TorusGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    Vec3 p = ray.at(crossing.t);
    Vec3 q = frame_.toLocal(p - center_);
    double rho = std::sqrt(q.x * q.x + q.y * q.y);
    double cx = rho > 0 ? q.x / rho : 1, cy = rho > 0 ? q.y / rho : 0;
    // From the nearest point of the core circle to q.
    Vec3 fromCore((rho - major_) * cx, (rho - major_) * cy, q.z);
    double len = glm::length(fromCore);
    Vec3 n = frame_.fromLocal(len > 0 ? fromCore / len : Vec3(cx, cy, 0));
    double distance = len - minor_;
    // Local coordinates round a few times relative to |p| + |centre|, the frame's axis is off
    // by a few roundings (moving points by that times their distance from the centre), and
    // ρ, ρ − R and the length add a few relative roundings of R + r.
    double distanceError = errorGamma(24) * (sumAbs(p) + sumAbs(center_) + major_ + minor_);
    RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = n;
    sp.shadingNormal = n;
    if (wantUv) {
        sp.uv = {angleCoordinate(q.y, q.x), angleCoordinate(q.z, rho - major_)};
        // u turns around the axis (radius ρ), v around the tube (radius r, from the core).
        sp.dpdu = frame_.fromLocal(2 * kPi * Vec3(-q.y, q.x, 0));
        sp.dpdv = frame_.fromLocal(2 * kPi * Vec3(-q.z * cx, -q.z * cy, rho - major_));
    }
    return sp;
}

} // namespace crt::tracer
