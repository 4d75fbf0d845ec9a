// The surface of revolution primitive: POV-Ray's sor, a radius given by cubics of the height.
#include "tracer/geometry/sor.hpp"

#include "tracer/geometry/polynomial_roots.hpp"

#include <algorithm>

namespace crt::tracer {

SorGeometry::SorGeometry(const scene::SorShape& desc) : open_(desc.open) {
    const std::vector<Vec2>& p = desc.points;
    if (p.size() < 4) return;
    auto segments = std::make_shared<std::vector<Segment>>();
    double most = 0;
    for (size_t i = 0; i + 3 < p.size(); ++i) {
        const double h = p[i + 2].y - p[i + 1].y;
        const double before = p[i + 2].y - p[i].y, after = p[i + 3].y - p[i + 1].y;
        if (!(h > 0) || before == 0 || after == 0) return;
        // The slopes of R = x² at the two points, from their neighbours, in units of s.
        const double m0 = h * 2 * p[i + 1].x * (p[i + 2].x - p[i].x) / before;
        const double m1 = h * 2 * p[i + 2].x * (p[i + 3].x - p[i + 1].x) / after;
        Segment s;
        s.y0 = p[i + 1].y;
        s.y1 = p[i + 2].y;
        s.k0 = p[i + 1].x * p[i + 1].x;
        s.k1 = p[i + 2].x * p[i + 2].x;
        s.c3 = 2 * s.k0 + m0 - 2 * s.k1 + m1;
        s.c2 = -3 * s.k0 - 2 * m0 + 3 * s.k1 - m1;
        s.c1 = m0;
        most = std::max({most, s.k0, s.k1});
        double r0, r1;
        if (solveQuadratic(3 * s.c3, s.c2, s.c1, r0, r1)) {
            for (double r : {r0, r1})
                if (r > 0 && r < 1) most = std::max(most, s.at(r));
        }
        segments->push_back(s);
    }
    const double r = std::sqrt(most);
    bounds_ = padded({Vec3(-r, segments->front().y0, -r), Vec3(r, segments->back().y1, r)});
    segments_ = std::move(segments);
}

void SorGeometry::crossSegment(const Ray& ray, size_t i, CrossingList& out) const {
    const Segment& seg = (*segments_)[i];
    const Vec2 o2(ray.origin.x, ray.origin.z), d2(ray.dir.x, ray.dir.z);
    auto rho2 = [&](double t) {
        const Vec2 q = o2 + t * d2;
        return glm::dot(q, q);
    };
    // Along the segment by s: the line's t is linear in it, x² + z² quadratic.
    const double t0 = (seg.y0 - ray.origin.y) / ray.dir.y;
    const double t1 = (seg.y1 - ray.origin.y) / ray.dir.y;
    const double q = (seg.y1 - seg.y0) / ray.dir.y;
    const double alpha = glm::dot(d2, d2) * q * q;
    const double beta = 2 * glm::dot(o2 + t0 * d2, d2) * q;
    // ρ² − R as a cubic in s (its constant term is the value at s = 0).
    const double g[4] = {rho2(t0) - seg.k0, beta - seg.c1, alpha - seg.c2, -seg.c3};
    polynomialSignChanges(
        g, 3, [&](double s) { return rho2(t0 + s * q) - seg.at(s); },
        [&](double s) { return 2 * glm::dot(o2 + (t0 + s * q) * d2, d2) * q - seg.slope(s); }, g[0],
        rho2(t1) - seg.k1, [&](double s) { out.add(t0 + s * q, static_cast<uint32_t>(2 + i)); });
}

void SorGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!segments_) return;
    const std::vector<Segment>& segments = *segments_;
    const Vec2 o2(ray.origin.x, ray.origin.z), d2(ray.dir.x, ray.dir.z);
    if (ray.dir.y == 0) {
        // A level line meets the side where x² + z² = R(y) at its own height, or nowhere.
        const double y = ray.origin.y;
        for (size_t i = 0; i < segments.size(); ++i) {
            const Segment& seg = segments[i];
            if (y < seg.y0 || y > seg.y1) continue;
            const double r = seg.at((y - seg.y0) / (seg.y1 - seg.y0));
            double ta, tb;
            if (r > 0 &&
                solveQuadratic(glm::dot(d2, d2), glm::dot(o2, d2), glm::dot(o2, o2) - r, ta, tb) &&
                ta < tb) {
                out.add(ta, static_cast<uint32_t>(2 + i));
                out.add(tb, static_cast<uint32_t>(2 + i));
            }
            return;
        }
        return;
    }
    for (size_t i = 0; i < segments.size(); ++i) crossSegment(ray, i, out);
    if (!open_) {
        // An end face where the line is inside the side there: the same test the side's
        // crossings start from, so the two agree at the rim.
        const Segment& first = segments.front();
        const Segment& last = segments.back();
        const double tBottom = (first.y0 - ray.origin.y) / ray.dir.y;
        const double tTop = (last.y1 - ray.origin.y) / ray.dir.y;
        const Vec2 qb = o2 + tBottom * d2, qt = o2 + tTop * d2;
        if (glm::dot(qb, qb) - first.k0 < 0) out.add(tBottom, 0);
        if (glm::dot(qt, qt) - last.k1 < 0) out.add(tTop, 1);
    }
    out.sortByT();
}

SurfacePoint SorGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const std::vector<Segment>& segments = *segments_;
    const Vec3 p = ray.at(crossing.t);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    SurfacePoint sp;
    if (crossing.part < 2) {
        const bool top = crossing.part == 1;
        const double h = top ? segments.back().y1 : segments.front().y0;
        const Vec3 n(0, top ? 1 : -1, 0);
        const RefinedPoint r =
            refineOntoSurface(p, n.y * (p.y - h), errorGamma(2) * (std::abs(p.y) + std::abs(h)), n);
        sp.point = r.point;
        sp.pointError = r.error;
        sp.normal = sp.shadingNormal = n;
        if (wantUv) {
            const double rim = std::sqrt(top ? segments.back().k1 : segments.front().k0);
            sp.uv = {angleCoordinate(p.z, p.x), top ? 2 - rho / rim : rho / rim - 1};
            sp.dpdu = 2 * kPi * Vec3(-p.z, 0, p.x);
            sp.dpdv = rho > 0 ? Vec3(p.x, 0, p.z) * ((top ? -rim : rim) / rho) : Vec3(rim, 0, 0);
        }
        return sp;
    }
    const size_t i = crossing.part - 2;
    const Segment& seg = segments[i];
    const double height = seg.y1 - seg.y0;
    const double s = clamp01((p.y - seg.y0) / height);
    const double dRdy = seg.slope(s) / height;
    // F = x² + z² − R(y), negative inside; its gradient points out.
    const Vec3 gradient(2 * p.x, -dRdy, 2 * p.z);
    const double len = glm::length(gradient);
    const Vec3 n = len > 0 ? gradient / len : Vec3(0, crossing.t * ray.dir.y > 0 ? -1 : 1, 0);
    const double f = rho * rho - seg.at(s);
    // F and R round relative to the sizes of their terms; s carries p.y's rounding.
    const double fError =
        errorGamma(24) * (rho * rho + seg.k0 + seg.k1 + std::abs(seg.c3) + std::abs(seg.c2) +
                          std::abs(seg.c1) + (std::abs(p.y) + std::abs(seg.y0)) * std::abs(dRdy));
    const double scale = len > 0 ? 1 / len : 0;
    const RefinedPoint r = refineOntoSurface(p, f * scale, fError * scale, n);
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    if (wantUv) {
        const double count = static_cast<double>(segments.size());
        sp.uv = {angleCoordinate(p.z, p.x), (static_cast<double>(i) + s) / count};
        sp.dpdu = 2 * kPi * Vec3(-p.z, 0, p.x);
        // Up the side: the radius changes by dR/ds / 2ρ as the height rises by `height`.
        const double drds = rho > 0 ? seg.slope(s) / (2 * rho) : 0;
        const Vec3 outward = rho > 0 ? Vec3(p.x, 0, p.z) / rho : Vec3(1, 0, 0);
        sp.dpdv = count * (drds * outward + Vec3(0, height, 0));
    }
    return sp;
}

} // namespace crt::tracer
