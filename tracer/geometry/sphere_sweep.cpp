// The sphere-sweep primitive: POV-Ray's sphere_sweep (see sphere_sweep.hpp).
#include "tracer/geometry/sphere_sweep.hpp"

#include "tracer/geometry/polynomial_roots.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

/// A polynomial in u, c[k] the coefficient of u^k.
struct Polynomial {
    double c[kMaxPolynomialDegree + 1] = {};
    int degree = 0;

    double operator()(double u) const { return evaluatePolynomial(c, degree, u).value; }
};

Polynomial derivative(const Polynomial& p) {
    Polynomial d;
    d.degree = std::max(p.degree - 1, 0);
    for (int k = 1; k <= p.degree; ++k) d.c[k - 1] = k * p.c[k];
    return d;
}

Polynomial product(const Polynomial& p, const Polynomial& q) {
    Polynomial r;
    r.degree = p.degree + q.degree;
    for (int i = 0; i <= p.degree; ++i)
        for (int j = 0; j <= q.degree; ++j) r.c[i + j] += p.c[i] * q.c[j];
    return r;
}

/// a·p − b·q.
Polynomial combination(double a, const Polynomial& p, double b, const Polynomial& q) {
    Polynomial r;
    r.degree = std::max(p.degree, q.degree);
    for (int k = 0; k <= p.degree; ++k) r.c[k] += a * p.c[k];
    for (int k = 0; k <= q.degree; ++k) r.c[k] -= b * q.c[k];
    return r;
}

/// The coefficients of a segment's centre (k for u^k) and of its radius.
struct SegmentTerms {
    Vec3 centre[4];
    double radius[4];
};

SegmentTerms termsOf(const scene::CurveSegmentOf<glm::dvec4>& s) {
    const glm::dvec4 k[4] = {s.d, s.c, s.b, s.a};
    SegmentTerms t;
    for (int i = 0; i < 4; ++i) {
        t.centre[i] = Vec3(k[i]);
        t.radius[i] = k[i].w;
    }
    return t;
}

} // namespace

SphereSweepGeometry::SphereSweepGeometry(const scene::SphereSweepShape& desc) {
    std::vector<glm::dvec4> spheres;
    for (size_t i = 0; i < desc.points.size() && i < desc.radii.size(); ++i)
        spheres.emplace_back(desc.points[i], desc.radii[i]);
    auto segments = std::make_shared<std::vector<Segment>>();
    for (const auto& curve :
         scene::curveSegmentsOf(std::span<const glm::dvec4>(spheres), desc.spline)) {
        Segment s{curve, desc.spline == scene::SplineKind::Linear ? 1 : 3, 0, {}};
        // The segment lies in the hull of its Bézier control points, its radius too.
        const glm::dvec4 control[4] = {curve.d, curve.d + curve.c / 3.0,
                                       curve.d + (2.0 * curve.c + curve.b) / 3.0, curve.end};
        for (const glm::dvec4& p : control) {
            const double r = std::abs(p.w);
            s.bounds.include(Bounds3::of(Vec3(p) - r, Vec3(p) + r));
        }
        for (const glm::dvec4& k : {curve.a, curve.b, curve.c, curve.d})
            s.size += std::abs(k.x) + std::abs(k.y) + std::abs(k.z) + std::abs(k.w);
        s.bounds = padded(s.bounds);
        bounds_.include(s.bounds);
        segments->push_back(s);
    }
    segments_ = std::move(segments);
}

void SphereSweepGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (glm::dot(ray.dir, ray.dir) == 0) return;
    thread_local std::vector<Span> spans;
    spans.clear();
    for (uint32_t i = 0; i < segments_->size(); ++i) {
        const Bounds3& box = (*segments_)[i].bounds;
        if (LineSpan span; lineSpan(ray, box.lo, box.hi, span)) crossSegment(ray, i, spans);
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.t0 < b.t0; });
    // The ends of the union of the spans, each with the segment whose sphere it lies on.
    for (size_t i = 0; i < spans.size();) {
        const Span& first = spans[i];
        double exit = first.t1;
        uint32_t exitSegment = first.segment;
        for (++i; i < spans.size() && spans[i].t0 <= exit; ++i) {
            if (spans[i].t1 > exit) {
                exit = spans[i].t1;
                exitSegment = spans[i].segment;
            }
        }
        out.add(first.t0, first.segment);
        out.add(exit, exitSegment);
    }
}

void SphereSweepGeometry::crossSegment(const Ray& ray, uint32_t i, std::vector<Span>& spans) const {
    const Segment& segment = (*segments_)[i];
    const SegmentTerms terms = termsOf(segment.curve);
    const int n = segment.degree;
    const Vec3& d = ray.dir;
    const double dd = glm::dot(d, d);
    // From the line's point nearest the segment's box, so that a far origin costs no precision.
    const double tc = glm::dot(segment.bounds.centroid() - ray.origin, d) / dd;
    const Vec3 o = ray.origin + tc * d;
    // With w(u) = c(u) − o: the line meets sphere u where dd·r² − |d × w|² ≥ 0, between
    // (d·w ∓ √that) / dd. Written with d × w, the discriminant has no cancellation.
    Vec3 cross[4];
    Polynomial along, discriminant;
    along.degree = n;
    discriminant.degree = 2 * n;
    for (int k = 0; k <= n; ++k) {
        const Vec3 w = k == 0 ? terms.centre[0] - o : terms.centre[k];
        cross[k] = glm::cross(d, w);
        along.c[k] = glm::dot(d, w);
    }
    for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k)
            discriminant.c[j + k] +=
                dd * terms.radius[j] * terms.radius[k] - glm::dot(cross[j], cross[k]);
    // The entry or exit stops moving where (d·w)'·√disc = ∓disc'/2, a root of the squared
    // form g = 4·(d·w)'²·disc − disc'². Where both sides vanish at once (a line square to a
    // straight segment) g only touches 0, so its turns are candidates too: entries and exits
    // at any u of the run are real, so a candidate too many costs time, not correctness.
    const Polynomial slope = derivative(along), discriminantSlope = derivative(discriminant);
    const Polynomial turns = combination(4, product(product(slope, slope), discriminant), 1,
                                         product(discriminantSlope, discriminantSlope));
    const Polynomial turnsSlope = derivative(turns);
    double turnAt[2 * kMaxPolynomialDegree], runEnds[kMaxPolynomialDegree + 2];
    int turnCount = polynomialRoots(turns.c, turns.degree, turnAt);
    turnCount += polynomialRoots(turnsSlope.c, turnsSlope.degree, turnAt + turnCount);
    runEnds[0] = 0;
    const int roots = polynomialRoots(discriminant.c, discriminant.degree, runEnds + 1);
    runEnds[roots + 1] = 1;

    auto entryAndExit = [&](double u, double& entry, double& exit) {
        const glm::dvec4 p = segment.curve.at(u);
        const Vec3 w = Vec3(p) - o;
        const Vec3 c = glm::cross(d, w);
        const double root = std::sqrt(std::max(0.0, dd * p.w * p.w - glm::dot(c, c)));
        const double a = glm::dot(d, w);
        entry = std::min(entry, (a - root) / dd);
        exit = std::max(exit, (a + root) / dd);
    };
    for (int r = 0; r <= roots; ++r) {
        const double u0 = runEnds[r], u1 = runEnds[r + 1];
        if (!(discriminant(0.5 * (u0 + u1)) >= 0)) continue;
        double entry = kInfinity, exit = -kInfinity;
        entryAndExit(u0, entry, exit);
        entryAndExit(u1, entry, exit);
        for (int k = 0; k < turnCount; ++k)
            if (turnAt[k] > u0 && turnAt[k] < u1) entryAndExit(turnAt[k], entry, exit);
        if (entry <= exit) spans.push_back({tc + entry, tc + exit, i});
    }
}

SurfacePoint SphereSweepGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    const Segment& segment = (*segments_)[crossing.part];
    const SegmentTerms terms = termsOf(segment.curve);
    const int n = segment.degree;
    const Vec3 p = ray.at(crossing.t);
    // The sphere the point lies on is the one it is least inside of: the least of
    // h(u) = |c(u) − p|² − r(u)², at an end of the segment or where h' = 0.
    Polynomial h;
    h.degree = 2 * n;
    for (int j = 0; j <= n; ++j) {
        const Vec3 wj = j == 0 ? terms.centre[0] - p : terms.centre[j];
        for (int k = 0; k <= n; ++k) {
            const Vec3 wk = k == 0 ? terms.centre[0] - p : terms.centre[k];
            h.c[j + k] += glm::dot(wj, wk) - terms.radius[j] * terms.radius[k];
        }
    }
    const Polynomial slope = derivative(h);
    double candidates[kMaxPolynomialDegree + 2] = {0, 1};
    const int count = 2 + polynomialRoots(slope.c, slope.degree, candidates + 2);
    double best = kInfinity;
    glm::dvec4 sphere(0.0);
    for (int k = 0; k < count; ++k) {
        const glm::dvec4 s = segment.curve.at(candidates[k]);
        const Vec3 f = p - Vec3(s);
        const double inside = glm::dot(f, f) - s.w * s.w;
        if (inside < best) {
            best = inside;
            sphere = s;
        }
    }
    const Vec3 f = p - Vec3(sphere);
    const double len = glm::length(f);
    const Vec3 normal = len > 0 ? f / len : Vec3(0, 1, 0);
    const double distance = len - std::abs(sphere.w);
    // The centre and radius round with the size of the segment's coefficients, p − c with p.
    const double distanceError = errorGamma(12) * (sumAbs(p) + segment.size + len);
    const RefinedPoint r = refineOntoSurface(p, distance, distanceError, normal);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = normal;
    return sp;
}

} // namespace crt::tracer
