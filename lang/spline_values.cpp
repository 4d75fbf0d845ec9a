// Spline values: a curve through space made from points as a Lathe's curve is, with a time
// at each point between its segments, read by spline(s, t) (camera paths, motion).
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

#include <algorithm>

namespace crt::lang {

Value Interpreter::buildSpline(ObjectBuilder& b) {
    SplineValue spline;
    const scene::SplineKind kind = splineKind(b, "kind");
    std::vector<glm::dvec3> points;
    for (const Value& p : *b.get("points")->list) points.push_back({p.v[0], p.v[1], p.v[2]});
    const std::string_view kindName = scene::kSplineKindNames[static_cast<int>(kind)];
    const size_t least = scene::minimumCurvePoints(kind);
    if (points.size() < least) {
        fail(b.where("points"), fmt::format("a Spline of kind {} needs at least {} points, not {}",
                                            kindName, least, points.size()));
    }
    if (kind == scene::SplineKind::Bezier && points.size() % 4 != 0) {
        fail(b.where("points"),
             fmt::format("a bezier Spline takes 4 points a segment: {} is not a multiple of 4",
                         points.size()));
    }
    spline.segments = scene::curveSegmentsOf(std::span<const glm::dvec3>(points), kind);
    if (const Value* times = b.get("times"); times && !times->list->empty()) {
        const size_t want = spline.segments.size() + 1;
        if (times->list->size() != want) {
            fail(b.where("times"),
                 fmt::format("this Spline has {} segment{}, so it takes {} times, one where each "
                             "begins and one at its end, not {}",
                             want - 1, want == 2 ? "" : "s", want, times->list->size()));
        }
        for (size_t i = 0; i < want; ++i) {
            spline.times.push_back((*times->list)[i].asDouble());
            if (i > 0 && !(spline.times[i] > spline.times[i - 1])) {
                fail(b.whereItem("times", i),
                     fmt::format("a Spline's times must rise: time {} ({:g}) is not after time "
                                 "{} ({:g})",
                                 i + 1, spline.times[i], i, spline.times[i - 1]));
            }
        }
    }
    charge(spline.segments.size() * sizeof(spline.segments[0]) +
           spline.times.size() * sizeof(double));
    spline.source = span(b.range);
    splines_.push_back(std::move(spline));
    return Value::object(ValueKind::Spline, b.info.type,
                         static_cast<uint32_t>(splines_.size() - 1));
}

glm::dvec3 Interpreter::splineAt(uint32_t index, double t) const {
    const SplineValue& spline = splines_[index];
    const size_t count = spline.segments.size();
    // Which segment, and how far along it: by the times, or evenly over [0, 1].
    double along;
    if (spline.times.empty()) {
        along = std::clamp(t, 0.0, 1.0) * static_cast<double>(count);
    } else {
        const std::vector<double>& times = spline.times;
        const double clamped = std::clamp(t, times.front(), times.back());
        const size_t i =
            std::min<size_t>(
                static_cast<size_t>(std::upper_bound(times.begin(), times.end(), clamped) -
                                    times.begin()),
                count) -
            1;
        along = static_cast<double>(i) + (clamped - times[i]) / (times[i + 1] - times[i]);
    }
    const size_t i = std::min(static_cast<size_t>(along), count - 1);
    return spline.segments[i].at(along - static_cast<double>(i));
}

} // namespace crt::lang
