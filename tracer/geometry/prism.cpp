// The prism primitive: POV-Ray's, an outline of curve segments swept along y.
#include "tracer/geometry/prism.hpp"

#include "tracer/geometry/curve_segment_math.hpp"
#include "tracer/geometry/polynomial_roots.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

double cross2(const Vec2& a, const Vec2& b) {
    return a.x * b.y - a.y * b.x;
}

/// Calls found(u) for each u in [0, 1] where g(p(u)) changes sign along the segment, g being
/// affine: g(p) = linear(p) + constant. The ends are the segment's points as written, so
/// neighbouring segments see the same sign where they meet.
template <class Linear, class Found>
void signChanges(const scene::CurveSegment& s, const Linear& linear, double constant,
                 const Found& found) {
    const double g[4] = {linear(s.d) + constant, linear(s.c), linear(s.b), linear(s.a)};
    polynomialSignChanges(
        g, 3, [&](double u) { return linear(s.at(u)) + constant; },
        [&](double u) { return linear(s.slope(u)); }, g[0], linear(s.end) + constant, found);
}

} // namespace

PrismGeometry::PrismGeometry(const scene::PrismShape& desc) {
    const scene::CurveLoops loops = scene::curveLoops(desc.points, desc.spline);
    from_ = std::min(desc.from, desc.to);
    to_ = std::max(desc.from, desc.to);
    conic_ = desc.conic;
    open_ = desc.open;
    if (loops.unclosedFrom >= 0 || loops.loops.empty() || !(from_ < to_)) return;
    auto shared = std::make_shared<Shared>(Shared{{}, Outline(loops.loops)});
    Vec2 lo(kInfinity), hi(-kInfinity);
    for (size_t i = 0; i < loops.loops.size(); ++i) {
        // Just inside the loop is solid when the loops around it are even in number; there
        // the solid is left of a counter-clockwise loop's direction.
        std::vector<std::vector<scene::CurveSegment>> others = loops.loops;
        others.erase(others.begin() + static_cast<std::ptrdiff_t>(i));
        const bool inHole = Outline(others).contains(loops.loops[i].front().d);
        const bool solidLeft = (signedArea(loops.loops[i]) > 0) != inHole;
        for (const scene::CurveSegment& s : loops.loops[i]) {
            Wall w{s, Vec2(kInfinity), Vec2(-kInfinity), solidLeft ? 1.0 : -1.0};
            includeSegment(s, w.lo, w.hi);
            lo = glm::min(lo, w.lo);
            hi = glm::max(hi, w.hi);
            shared->walls.push_back(w);
        }
    }
    shared_ = std::move(shared);
    for (double h : {from_, to_}) {
        const double s = conic_ ? h : 1;
        bounds_.include(Vec3(glm::min(lo * s, hi * s).x, h, glm::min(lo * s, hi * s).y));
        bounds_.include(Vec3(glm::max(lo * s, hi * s).x, h, glm::max(lo * s, hi * s).y));
    }
    bounds_ = padded(bounds_);
}

template <class Found>
void PrismGeometry::crossWall(const Ray& ray, const Wall& w, const Found& found) const {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.dir;
    if (!conic_) {
        // The wall's points on the line: where the curve crosses the line seen from above.
        const Vec2 o2(o.x, o.z), d2(d.x, d.z);
        const double dd = glm::dot(d2, d2);
        if (!(dd > 0)) return;
        const double c0 = cross2(d2, w.lo - o2), c1 = cross2(d2, Vec2(w.hi.x, w.lo.y) - o2);
        const double c2 = cross2(d2, w.hi - o2), c3 = cross2(d2, Vec2(w.lo.x, w.hi.y) - o2);
        if (std::min({c0, c1, c2, c3}) > 0 || std::max({c0, c1, c2, c3}) < 0) return;
        signChanges(
            w.curve, [&](const Vec2& v) { return cross2(d2, v); }, -cross2(d2, o2),
            [&](double u) { found(u, glm::dot(w.curve.at(u) - o2, d2) / dd); });
        return;
    }
    // A conic wall's point on the line lies on the ray from the apex through (x, 1, z) of
    // the curve, in the plane through the apex and the line, normal m.
    const Vec3 m = glm::cross(o, d);
    signChanges(
        w.curve, [&](const Vec2& v) { return m.x * v.x + m.z * v.y; }, m.y,
        [&](double u) {
            const Vec2 c = w.curve.at(u);
            const Vec3 q(c.x, 1, c.y);
            const Vec3 dq = glm::cross(d, q);
            const double dqq = glm::dot(dq, dq);
            if (dqq > 0) found(u, -glm::dot(glm::cross(o, q), dq) / dqq);
        });
}

void PrismGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!shared_) return;
    const std::vector<Wall>& walls = shared_->walls;
    for (size_t j = 0; j < walls.size(); ++j) {
        crossWall(ray, walls[j], [&](double, double t) {
            const double y = ray.origin.y + t * ray.dir.y;
            if (y >= from_ && y <= to_) out.add(t, static_cast<uint32_t>(2 + j));
        });
    }
    if (!open_ && ray.dir.y != 0) {
        for (int part = 0; part < 2; ++part) {
            const double h = part == 0 ? from_ : to_;
            if (conic_ && h == 0) continue; // the apex: no face
            const double t = (h - ray.origin.y) / ray.dir.y;
            const Vec3 p = ray.at(t);
            const double scale = conic_ ? h : 1;
            if (std::isfinite(t) && shared_->outline.contains(Vec2(p.x, p.z) / scale))
                out.add(t, static_cast<uint32_t>(part));
        }
    }
    out.sortByT();
}

Vec3 PrismGeometry::wallNormal(const Wall& w, double u, double y) const {
    Vec2 tangent = w.curve.slope(u);
    if (tangent == Vec2(0.0)) // a cusp: the chord around it
        tangent = w.curve.at(std::min(u + 1e-6, 1.0)) - w.curve.at(std::max(u - 1e-6, 0.0));
    const Vec2 n2 = w.outward * Vec2(tangent.y, -tangent.x);
    if (!conic_) return glm::normalize(Vec3(n2.x, 0, n2.y));
    // Across the wall's directions (tangent·y, 0) and (x, 1, z) of the curve point; below
    // the apex the section is turned half round, and so is its outside.
    const Vec2 c = w.curve.at(u);
    const Vec3 n(n2.x, -glm::dot(n2, c), n2.y);
    return glm::normalize(y < 0 ? -n : n);
}

SurfacePoint PrismGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const Vec3 p = ray.at(crossing.t);
    const double size = std::max(sumAbs(bounds_.lo), sumAbs(bounds_.hi));
    SurfacePoint sp;
    if (crossing.part < 2) {
        const double h = crossing.part == 0 ? from_ : to_;
        const Vec3 n(0, crossing.part == 0 ? -1 : 1, 0);
        const RefinedPoint r =
            refineOntoSurface(p, n.y * (p.y - h), errorGamma(2) * (std::abs(p.y) + std::abs(h)), n);
        sp.point = r.point;
        sp.pointError = r.error;
        sp.normal = sp.shadingNormal = n;
        sp.uv = {p.x, p.z};
        sp.dpdu = {1, 0, 0};
        sp.dpdv = {0, 0, 1};
        return sp;
    }
    const std::vector<Wall>& walls = shared_->walls;
    const size_t j = crossing.part - 2;
    const Wall& w = walls[j];
    // The curve parameter of this crossing: found again, the one nearest in t.
    double u = 0, nearest = kInfinity;
    crossWall(ray, w, [&](double ur, double t) {
        if (std::abs(t - crossing.t) < nearest) {
            nearest = std::abs(t - crossing.t);
            u = ur;
        }
    });
    const Vec3 n = wallNormal(w, u, p.y);
    const Vec2 c = w.curve.at(u);
    const double scale = conic_ ? p.y : 1;
    const Vec3 onWall(c.x * scale, p.y, c.y * scale);
    const double distance = glm::dot(p - onWall, n);
    // The point, the curve's evaluation and the root's tolerance in u, each a few roundings of
    // the prism's size; the slope carries the last.
    const double distanceError =
        errorGamma(32) * (sumAbs(p) + size) * (1 + glm::length(w.curve.slope(u)));
    const RefinedPoint r = refineOntoSurface(p, distance, distanceError, n);
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    if (wantUv) {
        const double count = static_cast<double>(walls.size());
        const Vec2 slope = w.curve.slope(u) * scale * count;
        sp.uv = {(static_cast<double>(j) + u) / count, (p.y - from_) / (to_ - from_)};
        sp.dpdu = {slope.x, 0, slope.y};
        sp.dpdv = (to_ - from_) * (conic_ ? Vec3(c.x, 1, c.y) : Vec3(0, 1, 0));
    }
    return sp;
}

} // namespace crt::tracer
