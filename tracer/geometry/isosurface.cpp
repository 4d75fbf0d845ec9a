// The isosurface primitive: POV-Ray's, the solid where a compiled Function is below a
// threshold, within a box.
#include "tracer/geometry/isosurface.hpp"

#include "tracer/geometry/geometry_math.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace crt::tracer {

namespace {

/// Raises `slot` to `value` if it is lower, whatever other threads do meanwhile.
void raiseTo(std::atomic<double>& slot, double value) {
    double seen = slot.load(std::memory_order_relaxed);
    while (value > seen && !slot.compare_exchange_weak(seen, value, std::memory_order_relaxed)) {
    }
}

bool inside(double g) { return g <= 0; }

/// A span of the line still to search, and the function's values at its ends.
struct Span {
    double a, b, ga, gb;
};

} // namespace

IsosurfaceGeometry::IsosurfaceGeometry(const scene::IsosurfaceShape& shape, uint64_t maxEvaluations)
    : desc_(shape.desc), box_(scene::BoxShape{shape.desc->boundsMin, shape.desc->boundsMax}),
      maxEvaluations_(maxEvaluations), findings_(std::make_shared<IsosurfaceFindings>()) {}

double IsosurfaceGeometry::rootBetween(const Ray& ray, double ta, double tb, double ga, double gb,
                                       uint64_t& evaluations) const {
    // Illinois: regula falsi that halves the value kept at an end twice in a row, so that
    // convergence stays superlinear; bisection where the secant falls outside.
    int keptSide = 0;
    for (int i = 0; i < 60 && tb - ta > 1e-13 * (std::abs(ta) + std::abs(tb)) + 1e-300; ++i) {
        double t = (ta * gb - tb * ga) / (gb - ga);
        if (!(t > ta && t < tb)) t = 0.5 * (ta + tb);
        const double g = valueAt(ray.at(t));
        ++evaluations;
        if (inside(g) == inside(ga)) {
            ta = t, ga = g;
            if (keptSide == 1) gb *= 0.5;
            keptSide = 1;
        } else {
            tb = t, gb = g;
            if (keptSide == -1) ga *= 0.5;
            keptSide = -1;
        }
    }
    return 0.5 * (ta + tb);
}

bool IsosurfaceGeometry::search(const Ray& ray, double ta, double tb, double ga, double gb,
                                CrossingVisitor visit) const {
    const double dirLength = glm::length(ray.dir);
    const double slopeBound = desc_->maxGradient * dirLength; // of the function, per unit of t
    const double finest = desc_->accuracy / dirLength;
    uint64_t evaluations = 2;
    double steepest = 0;
    bool cutShort = false, goOn = true;
    // Depth first, the nearer half first, so that crossings come in order; each halving adds
    // one span to the stack, and the spans cannot be halved below the double's precision.
    std::array<Span, 1100> pending;
    int count = 0;
    pending[count++] = {ta, tb, ga, gb};
    while (count > 0 && goOn) {
        const Span s = pending[--count];
        const double length = s.b - s.a;
        if (length > 0) steepest = std::max(steepest, std::abs(s.gb - s.ga) / (length * dirLength));
        const bool sidesDiffer = inside(s.ga) != inside(s.gb);
        if (!sidesDiffer && std::abs(s.ga) + std::abs(s.gb) >= slopeBound * length) continue;
        if (length <= finest || count + 2 > static_cast<int>(pending.size()) || !(s.a < 0.5 * (s.a + s.b))) {
            if (sidesDiffer) goOn = visit({rootBetween(ray, s.a, s.b, s.ga, s.gb, evaluations), 0});
            continue;
        }
        if (evaluations >= maxEvaluations_) {
            cutShort = true;
            break;
        }
        const double m = 0.5 * (s.a + s.b);
        const double gm = valueAt(ray.at(m));
        ++evaluations;
        pending[count++] = {m, s.b, gm, s.gb};
        pending[count++] = {s.a, m, s.ga, gm};
    }
    raiseTo(findings_->steepestGradient, steepest);
    if (cutShort) findings_->searchesCutShort.fetch_add(1, std::memory_order_relaxed);
    return goOn;
}

void IsosurfaceGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    auto add = [&](const Crossing& c) {
        out.add(c.t, c.part);
        return true;
    };
    crossingsIn(ray, -kInfinity, kInfinity, add);
}

bool IsosurfaceGeometry::crossingsIn(const Ray& ray, double tMin, double tMax, CrossingVisitor visit) const {
    CrossingList faces;
    box_.crossLine(ray, faces);
    if (faces.count < 2) return true;
    const double tEnter = faces[0].t, tExit = faces[1].t;
    if (tExit <= tMin || tEnter >= tMax) return true;
    // The span of the line inside both the box and the window; a face ends it only where the
    // window holds it.
    const double ta = std::max(tEnter, tMin), tb = std::min(tExit, tMax);
    const double ga = valueAt(ray.at(ta)), gb = valueAt(ray.at(tb));
    const bool closed = !desc_->open;
    if (closed && tEnter > tMin && inside(ga) && !visit({tEnter, 1 + faces[0].part})) return false;
    auto inWindow = [&](const Crossing& c) { return !(c.t > tMin && c.t < tMax) || visit(c); };
    if (!search(ray, ta, tb, ga, gb, inWindow)) return false;
    return !(closed && tExit < tMax && inside(gb)) || visit({tExit, 1 + faces[1].part});
}

SurfacePoint IsosurfaceGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    if (crossing.part > 0) return box_.surfaceAt(ray, {crossing.t, crossing.part - 1}, wantUv);
    const Vec3 p = ray.at(crossing.t);
    // Central differences, with a step near the cube root of the precision relative to the
    // point's size: the truncation and rounding errors are then about even.
    const double scale = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double h = 1e-5 * scale;
    Vec3 gradient;
    for (int k = 0; k < 3; ++k) {
        Vec3 step(0.0);
        step[k] = h;
        gradient[k] = (valueAt(p + step) - valueAt(p - step)) / (2 * h);
    }
    const double length = glm::length(gradient);
    const Vec3 n = length > 0 && std::isfinite(length) ? gradient / length : Vec3(0, 1, 0);
    const double distance = length > 0 && std::isfinite(length) ? valueAt(p) / length : 0;
    // The function's own rounding is unknown: allow a part in 10⁹ of the point's size.
    const RefinedPoint r = refineOntoSurface(p, distance, 1e-9 * scale, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    return sp;
}

std::string IsosurfaceGeometry::warnings(const std::string& where) const {
    std::string text;
    const double found = findings_->steepestGradient.load();
    const double given = desc_->maxGradient;
    // POV-Ray's measures: a gradient found above the one given leaves holes; one far below it
    // costs time.
    if (found > given * 1.0001) {
        text += fmt::format("{}: warning: the function of this Isosurface changes by up to {:.3f} a "
                            "unit, more than its maxgradient {:g}; parts of it may be missing "
                            "(set maxgradient to {:.3f})\n",
                            where, found, given, found * 1.05);
    } else if (found > 1e-10 && (given - found >= 10 || (given / found >= 1.1 && given - found >= 0.5))) {
        text += fmt::format("{}: warning: the function of this Isosurface changes by at most {:.3f} "
                            "a unit, far below its maxgradient {:g}; a maxgradient of {:.3f} "
                            "would render faster\n",
                            where, found, given, found * 1.05);
    }
    if (const uint64_t cut = findings_->searchesCutShort.load()) {
        text += fmt::format("{}: warning: the search for this Isosurface along {} line{} stopped "
                            "after {} evaluations of its function; parts of it may be missing "
                            "(raise --max-isosurface-evaluations, or raise its accuracy)\n",
                            where, cut, cut == 1 ? "" : "s", maxEvaluations_);
    }
    return text;
}

} // namespace crt::tracer
