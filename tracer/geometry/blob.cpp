// The blob primitive: POV-Ray's, the solid where a sum of smooth fields passes a threshold.
#include "tracer/geometry/blob.hpp"

#include "tracer/geometry/polynomial_roots.hpp"

#include <algorithm>

namespace crt::tracer {

/// One piece of a component along a line: where the line is within reach of a point (a
/// sphere, a cylinder's end) or of an axis (a cylinder's body), the squared distance is the
/// quadratic q(t) = A·t² + B·t + C, and the field strength · (1 − q / r²)².
struct BlobGeometry::Piece {
    double t0, t1;
    double A, B, C;
    const Vec3* centre; ///< the point the distance is from, or null for the axis
    uint32_t component;
};

bool BlobGeometry::pointReach(const Ray& ray, const Vec3& c, double r2, Piece& piece) {
    const Vec3 w = ray.origin - c;
    piece.A = glm::dot(ray.dir, ray.dir);
    piece.B = 2 * glm::dot(w, ray.dir);
    piece.C = glm::dot(w, w);
    piece.centre = &c;
    return solveQuadratic(piece.A, 0.5 * piece.B, piece.C - r2, piece.t0, piece.t1) &&
           piece.t0 < piece.t1;
}

BlobGeometry::BlobGeometry(const scene::BlobShape& desc) {
    if (!desc.desc) return;
    threshold_ = desc.desc->threshold;
    auto components = std::make_shared<std::vector<Component>>();
    for (const scene::BlobComponent& c : desc.desc->components) {
        const Vec3 axis = c.cylinder ? c.b - c.a : Vec3(0.0);
        components->push_back(
            {c.a, c.a + axis, axis, glm::dot(axis, axis), c.radius * c.radius, c.strength});
        // Only what adds to the field can be inside.
        if (c.strength > 0) {
            bounds_.include(Bounds3::of(glm::min(c.a, c.a + axis) - c.radius,
                                        glm::max(c.a, c.a + axis) + c.radius));
        }
    }
    bounds_ = padded(bounds_);
    components_ = std::move(components);
}

double BlobGeometry::fieldAt(const Vec3& p, Vec3* gradient, double* error) const {
    double field = 0;
    if (gradient) *gradient = Vec3(0.0);
    if (error) *error = 0;
    for (const Component& c : *components_) {
        // The nearest point of the component's centre or segment.
        Vec3 nearest = c.a;
        if (c.axisLength2 > 0)
            nearest += clamp01(glm::dot(p - c.a, c.axis) / c.axisLength2) * c.axis;
        const Vec3 v = p - nearest;
        const double d2 = glm::dot(v, v);
        if (!(d2 < c.radius2)) continue;
        const double w = 1 - d2 / c.radius2;
        field += c.strength * w * w;
        if (gradient) *gradient -= (4 * c.strength * w / c.radius2) * v;
        // d² rounds relative to the sizes of the point and the component; the rest a little.
        const double size = sumAbs(p) + sumAbs(c.a) + sumAbs(c.axis);
        if (error)
            *error += std::abs(c.strength) *
                      (errorGamma(8) + 4 * errorGamma(6) * size * size / c.radius2);
    }
    return field;
}

double BlobGeometry::pieceField(const Piece& p, const Vec3& x) const {
    const Component& c = (*components_)[p.component];
    Vec3 v = x - (p.centre ? *p.centre : c.a);
    if (!p.centre) v -= (glm::dot(v, c.axis) / c.axisLength2) * c.axis;
    const double w = std::max(0.0, 1 - glm::dot(v, v) / c.radius2);
    return c.strength * w * w;
}

void BlobGeometry::addPieces(const Ray& ray, uint32_t i, std::vector<Piece>& pieces) const {
    const Component& c = (*components_)[i];
    Piece piece{};
    piece.component = i;
    if (c.axisLength2 == 0) {
        if (pointReach(ray, c.a, c.radius2, piece)) pieces.push_back(piece);
        return;
    }
    // Along the axis, s = (wa + t·da) / |axis|²: the end planes are where s = 0 and s = 1.
    const Vec3 w = ray.origin - c.a;
    const double wa = glm::dot(w, c.axis), da = glm::dot(ray.dir, c.axis);
    const double s0 = -wa / da, s1 = (c.axisLength2 - wa) / da; // by t, when da ≠ 0
    const double sLevel = wa / c.axisLength2;                   // s throughout, when da = 0
    // The body: within reach of the axis, between the planes.
    Piece body{};
    body.component = i;
    body.A = glm::dot(ray.dir, ray.dir) - da * da / c.axisLength2;
    body.B = 2 * (glm::dot(w, ray.dir) - wa * da / c.axisLength2);
    body.C = glm::dot(w, w) - wa * wa / c.axisLength2;
    bool reach;
    if (body.A > 0) {
        reach = solveQuadratic(body.A, 0.5 * body.B, body.C - c.radius2, body.t0, body.t1);
    } else { // along the axis: at one distance from it throughout
        reach = body.C < c.radius2;
        body.t0 = -kInfinity;
        body.t1 = kInfinity;
    }
    if (da != 0) {
        body.t0 = std::max(body.t0, std::min(s0, s1));
        body.t1 = std::min(body.t1, std::max(s0, s1));
    } else if (sLevel < 0 || sLevel > 1) {
        reach = false;
    }
    if (reach && body.t0 < body.t1) pieces.push_back(body);
    // The round ends, each beyond its plane: the base where s < 0, the top where s > 1.
    for (int end = 0; end < 2; ++end) {
        Piece cap{};
        cap.component = i;
        if (!pointReach(ray, end == 0 ? c.a : c.b, c.radius2, cap)) continue;
        const double plane = end == 0 ? s0 : s1;
        // s < 0 comes before the base's plane when the line runs along the axis (da > 0);
        // s > 1 after the top's.
        const bool beyondBefore = (end == 0) == (da > 0);
        if (da == 0) {
            if (end == 0 ? !(sLevel < 0) : !(sLevel > 1)) continue;
        } else if (beyondBefore) {
            cap.t1 = std::min(cap.t1, plane);
        } else {
            cap.t0 = std::max(cap.t0, plane);
        }
        if (cap.t0 < cap.t1) pieces.push_back(cap);
    }
}

void BlobGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    if (!components_) return;
    thread_local std::vector<Piece> pieces;
    thread_local std::vector<double> ends, gaps;
    pieces.clear();
    ends.clear();
    for (uint32_t i = 0; i < components_->size(); ++i) addPieces(ray, i, pieces);
    for (const Piece& p : pieces) {
        ends.push_back(p.t0);
        ends.push_back(p.t1);
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    // threshold − field at each end, once, so that neighbouring spans agree on its sign.
    gaps.clear();
    for (double t : ends) {
        const Vec3 x = ray.at(t);
        double gap = threshold_;
        // A cylinder's pieces meet at its end planes with the same field: count one.
        uint32_t counted = UINT32_MAX;
        for (const Piece& p : pieces) {
            if (p.t0 <= t && p.t1 >= t && p.component != counted) {
                gap -= pieceField(p, x);
                counted = p.component;
            }
        }
        gaps.push_back(gap);
    }
    for (size_t k = 0; k + 1 < ends.size(); ++k)
        crossSpan(ray, ends[k], ends[k + 1], gaps[k], gaps[k + 1], pieces, out);
}

void BlobGeometry::crossSpan(const Ray& ray, double ta, double tb, double gapA, double gapB,
                             const std::vector<Piece>& pieces, CrossingList& out) const {
    const std::vector<Component>& components = *components_;
    const double h = tb - ta;
    // threshold − Σ strength · (1 − q/r²)² as a quartic in u = (t − ta) / h.
    double g[5] = {threshold_, 0, 0, 0, 0};
    thread_local std::vector<const Piece*> active;
    active.clear();
    // The most the field can reach in the span, from each piece's least distance in it: a
    // span of the reaches' outskirts never passes the threshold, and is left at that.
    double most = 0;
    for (const Piece& p : pieces) {
        if (!(p.t0 <= ta && p.t1 >= tb)) continue;
        active.push_back(&p);
        const Component& c = components[p.component];
        if (c.strength > 0) {
            const double t = p.A > 0 ? std::clamp(-p.B / (2 * p.A), ta, tb) : ta;
            const double q = std::min({(p.A * t + p.B) * t + p.C, (p.A * ta + p.B) * ta + p.C,
                                       (p.A * tb + p.B) * tb + p.C});
            const double w = std::max(0.0, 1 - q / c.radius2);
            most += c.strength * w * w;
        }
    }
    if (active.empty() || most < threshold_ * (1 - 1e-9)) return; // outside throughout
    for (const Piece* piece : active) {
        const Piece& p = *piece;
        const Component& c = components[p.component];
        const double q0 = (p.A * ta + p.B) * ta + p.C, q1 = (2 * p.A * ta + p.B) * h,
                     q2 = p.A * h * h;
        const double w0 = 1 - q0 / c.radius2, w1 = -q1 / c.radius2, w2 = -q2 / c.radius2;
        g[0] -= c.strength * w0 * w0;
        g[1] -= c.strength * 2 * w0 * w1;
        g[2] -= c.strength * (w1 * w1 + 2 * w0 * w2);
        g[3] -= c.strength * 2 * w1 * w2;
        g[4] -= c.strength * w2 * w2;
    }
    // The same from the point itself, which rounds less than the coefficients.
    auto gapAt = [&](double u, double* slope) {
        const double t = ta + u * h;
        const Vec3 x = ray.at(t);
        double gap = threshold_, dgap = 0;
        for (const Piece* p : active) {
            gap -= pieceField(*p, x);
            if (!slope) continue;
            const Component& c = components[p->component];
            const double q = (p->A * t + p->B) * t + p->C;
            dgap += c.strength * 2 * (1 - q / c.radius2) * (2 * p->A * t + p->B) * h / c.radius2;
        }
        if (slope) *slope = dgap;
        return gap;
    };
    polynomialSignChanges(
        g, 4, [&](double u) { return gapAt(u, nullptr); },
        [&](double u) {
            double slope;
            gapAt(u, &slope);
            return slope;
        },
        gapA, gapB, [&](double u) { out.add(ta + u * h, 0); });
}

SurfacePoint BlobGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool) const {
    const Vec3 p = ray.at(crossing.t);
    Vec3 gradient;
    double fieldError;
    const double field = fieldAt(p, &gradient, &fieldError);
    const double len = glm::length(gradient);
    const Vec3 n = len > 0 ? -gradient / len : Vec3(0, 1, 0);
    const double scale = len > 0 ? 1 / len : 0;
    const RefinedPoint r =
        refineOntoSurface(p, (threshold_ - field) * scale, fieldError * scale, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    return sp;
}

} // namespace crt::tracer
