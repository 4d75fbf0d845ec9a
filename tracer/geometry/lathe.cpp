// The lathe primitive: POV-Ray's, a curve in the x-y plane turned about the y axis.
#include "tracer/geometry/lathe.hpp"

#include "tracer/geometry/curve_segment_math.hpp"
#include "tracer/geometry/polynomial_roots.hpp"

#include <algorithm>
#include <array>

namespace crt::tracer {

namespace {

using Cubic = std::array<double, 4>; ///< coefficients, constant first

Cubic component(const scene::CurveSegment& s, int axis) {
    return {s.d[axis], s.c[axis], s.b[axis], s.a[axis]};
}

std::array<double, 7> square(const Cubic& k) {
    std::array<double, 7> out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i + j] += k[i] * k[j];
    return out;
}

} // namespace

LatheGeometry::LatheGeometry(const scene::LatheShape& desc) {
    const std::vector<scene::CurveSegment> curve = scene::curveSegments(desc.points, desc.spline);
    if (curve.empty()) return;
    auto segments = std::make_shared<std::vector<Segment>>();
    Vec2 lo(curve.front().d), hi(lo);
    for (const scene::CurveSegment& c : curve) {
        Vec2 segLo(c.d), segHi(segLo);
        includeSegment(c, segLo, segHi);
        const double r = std::max(std::abs(segLo.x), std::abs(segHi.x));
        segments->push_back({c, segLo.y, segHi.y, r});
        lo = glm::min(lo, segLo);
        hi = glm::max(hi, segHi);
    }
    const double radius = std::max(std::abs(lo.x), std::abs(hi.x));
    solid_ = scene::curveEnclosesSolid(curve);
    // A curve from the axis to the axis is closed by the axis, where x = 0 adds no area.
    outward_ = signedArea(curve) >= 0 ? 1 : -1;
    bounds_ = padded({Vec3(-radius, lo.y, -radius), Vec3(radius, hi.y, radius)});
    segments_ = std::move(segments);
}

namespace {

/// Newton's method on the line meeting the curve, (y(u) − y(t), x(u)² − ρ(t)²) = 0, from a
/// root u found on a polynomial whose coefficients lose digits for lines almost level; the
/// line's t, or the guess when it does not converge within the segment.
double polishedT(const Ray& ray, const scene::CurveSegment& curve, double u, double t) {
    const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
    double best = t;
    for (int i = 0; i < 4; ++i) {
        const Vec2 c = curve.at(u), s = curve.slope(u);
        const Vec2 q = o + t * d;
        const double g0 = c.y - ray.origin.y - t * ray.dir.y;
        const double g1 = c.x * c.x - glm::dot(q, q);
        const double j00 = s.y, j01 = -ray.dir.y, j10 = 2 * c.x * s.x, j11 = -2 * glm::dot(q, d);
        const double det = j00 * j11 - j01 * j10;
        if (!(std::abs(det) > 0)) break;
        const double du = (g0 * j11 - j01 * g1) / det, dt = (j00 * g1 - j10 * g0) / det;
        u -= du;
        t -= dt;
        if (!std::isfinite(t) || !(u >= -1e-9 && u <= 1 + 1e-9)) break;
        best = t;
        if (std::abs(dt) <= 0x1p-52 * std::abs(t)) break;
    }
    return best;
}

} // namespace

void LatheGeometry::crossSegment(const Ray& ray, uint32_t i, CrossingList& out) const {
    const Segment& seg = (*segments_)[i];
    const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
    const double dy = ray.dir.y;
    // A quick miss: within the segment's heights, the line stays farther from the axis.
    double ta = (seg.yLo - ray.origin.y) / dy, tb = (seg.yHi - ray.origin.y) / dy;
    if (ta > tb) std::swap(ta, tb);
    const double dd = glm::dot(d, d);
    const double nearest = dd > 0 ? std::clamp(-glm::dot(o, d) / dd, ta, tb) : ta;
    const Vec2 q = o + nearest * d;
    const double slack =
        errorGamma(8) * (sumAbs(Vec3(o, 0)) + std::abs(nearest) * sumAbs(Vec3(d, 0)));
    if (std::sqrt(glm::dot(q, q)) > seg.radius * (1 + errorGamma(8)) + slack) return;
    // By u along the segment, the line's t is (y(u) − oy) / dy, and dy² (ρ(t)² − x(u)²) is
    // |d·w + dy·o|² − (dy·x)² with w = y(u) − oy: a polynomial of degree 6.
    Cubic w = component(seg.curve, 1);
    w[0] -= ray.origin.y;
    Cubic qx{}, qz{}, x = component(seg.curve, 0);
    for (int k = 0; k < 4; ++k) {
        qx[k] = d.x * w[k];
        qz[k] = d.y * w[k];
        x[k] *= dy;
    }
    qx[0] += dy * o.x;
    qz[0] += dy * o.y;
    const std::array<double, 7> sx = square(qx), sz = square(qz), sr = square(x);
    double f[7];
    for (int k = 0; k < 7; ++k) f[k] = sx[k] + sz[k] - sr[k];
    auto valueAt = [&](const Vec2& c) {
        const Vec2 p = d * (c.y - ray.origin.y) + dy * o;
        const double r = dy * c.x;
        return glm::dot(p, p) - r * r;
    };
    polynomialSignChanges(
        f, 6, [&](double u) { return valueAt(seg.curve.at(u)); },
        [&](double u) {
            const Vec2 c = seg.curve.at(u), s = seg.curve.slope(u);
            const Vec2 p = d * (c.y - ray.origin.y) + dy * o;
            return 2 * glm::dot(p, d) * s.y - 2 * dy * dy * c.x * s.x;
        },
        valueAt(seg.curve.d), valueAt(seg.curve.end),
        [&](double u) {
            const double t = (seg.curve.at(u).y - ray.origin.y) / dy;
            out.add(polishedT(ray, seg.curve, u, t), i);
        });
}

void LatheGeometry::crossLevel(const Ray& ray, CrossingList& out) const {
    const std::vector<Segment>& segments = *segments_;
    const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
    const double dd = glm::dot(d, d);
    // The line's height where it passes the axis closest; it barely changes over the lathe.
    const double h = ray.origin.y - ray.dir.y * glm::dot(o, d) / dd;
    for (uint32_t i = 0; i < segments.size(); ++i) {
        const Segment& seg = segments[i];
        if (h < seg.yLo || h > seg.yHi) continue;
        Cubic y = component(seg.curve, 1);
        y[0] -= h;
        polynomialSignChanges(
            y.data(), 3, [&](double u) { return seg.curve.at(u).y - h; },
            [&](double u) { return seg.curve.slope(u).y; }, seg.curve.d.y - h, seg.curve.end.y - h,
            [&](double u) {
                const double r = seg.curve.at(u).x;
                double t0, t1;
                if (solveQuadratic(dd, glm::dot(o, d), glm::dot(o, o) - r * r, t0, t1) && t0 < t1) {
                    out.add(polishedT(ray, seg.curve, u, t0), i);
                    out.add(polishedT(ray, seg.curve, u, t1), i);
                }
            });
    }
}

void LatheGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!segments_) return;
    const double level = std::sqrt(ray.dir.x * ray.dir.x + ray.dir.z * ray.dir.z);
    // Below this slope the degree-6 polynomial's coefficients lose the line's height change.
    if (std::abs(ray.dir.y) <= 0x1p-26 * level) {
        crossLevel(ray, out);
    } else {
        for (uint32_t i = 0; i < segments_->size(); ++i) crossSegment(ray, i, out);
    }
    out.sortByT();
}

double LatheGeometry::nearestParameter(const Segment& seg, Vec2 point) const {
    const scene::CurveSegment& c = seg.curve;
    double candidates[2 + 2 * 3] = {0, 1};
    int n = 2;
    for (int axis = 0; axis < 2; ++axis) {
        Cubic k = component(c, axis);
        k[0] -= point[axis];
        n += polynomialRoots(k.data(), 3, candidates + n);
    }
    auto distance2 = [&](double u) {
        const Vec2 e = c.at(u) - point;
        return glm::dot(e, e);
    };
    double u = candidates[0];
    for (int i = 1; i < n; ++i)
        if (distance2(candidates[i]) < distance2(u)) u = candidates[i];
    // Newton's method on (c(u) − point)·c'(u) = 0, the nearest point's condition.
    for (int i = 0; i < 3; ++i) {
        const Vec2 e = c.at(u) - point, s = c.slope(u), s2 = 6.0 * c.a * u + 2.0 * c.b;
        const double g = glm::dot(e, s), slope = glm::dot(s, s) + glm::dot(e, s2);
        if (!(slope > 0)) break;
        u = clamp01(u - g / slope);
    }
    return u;
}

SurfacePoint LatheGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const std::vector<Segment>& segments = *segments_;
    const Segment& seg = segments[crossing.part];
    const Vec3 p = ray.at(crossing.t);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const Vec2 point(rho, p.y);
    const double u = nearestParameter(seg, point);
    const Vec2 c = seg.curve.at(u), s = seg.curve.slope(u);
    Vec2 n2 = outward_ * Vec2(s.y, -s.x);
    const double len = glm::length(n2);
    n2 = len > 0 ? n2 / len : Vec2(1, 0);
    const Vec3 radial = rho > 0 ? Vec3(p.x / rho, 0, p.z / rho) : Vec3(1, 0, 0);
    const Vec3 n = rho > 0 || n2.y == 0 ? n2.x * radial + Vec3(0, n2.y, 0)
                                        : Vec3(0, std::copysign(1.0, n2.y), 0);
    // The distance in the x-y plane, rounding with the curve's coefficients and the point.
    const scene::CurveSegment& k = seg.curve;
    const double size =
        glm::dot(glm::abs(k.a) + glm::abs(k.b) + glm::abs(k.c) + glm::abs(k.d), Vec2(1.0));
    const RefinedPoint r = refineOntoSurface(p, glm::dot(point - c, n2),
                                             errorGamma(32) * (rho + std::abs(p.y) + size), n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    if (wantUv) {
        const double count = static_cast<double>(segments.size());
        sp.uv = {angleCoordinate(p.z, p.x), (crossing.part + u) / count};
        sp.dpdu = 2 * kPi * Vec3(-p.z, 0, p.x);
        sp.dpdv = count * (s.x * radial + Vec3(0, s.y, 0));
    }
    return sp;
}

} // namespace crt::tracer
