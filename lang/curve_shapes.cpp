// The shapes made from curves of points: Prism, Sor, Lathe and SphereSweep, checked as
// POV-Ray checks their points, and the spline kind their attributes name.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

#include "scene/curve_outline.hpp"

namespace crt::lang {

scene::SplineKind splineKind(ObjectBuilder& b, std::string_view attribute) {
    const std::string spline = b.lowerText(attribute);
    for (size_t i = 0; i < std::size(scene::kSplineKindNames); ++i)
        if (spline == scene::kSplineKindNames[i]) return static_cast<scene::SplineKind>(i);
    return scene::SplineKind::Linear;
}

void Interpreter::checkPointCount(ObjectBuilder& b, scene::SplineKind kind, size_t least) {
    const size_t count = b.get("points")->list->size();
    const std::string_view kindName = scene::kSplineKindNames[static_cast<int>(kind)];
    if (count < least) {
        fail(b.where("points"),
             fmt::format("a {} with a {} spline needs at least {} points, not {}", b.info.name,
                         kindName, least, count));
    }
    if (kind == scene::SplineKind::Bezier && count % 4 != 0) {
        fail(b.where("points"),
             fmt::format("a {} with a bezier spline takes 4 points a segment: {} is not a "
                         "multiple of 4",
                         b.info.name, count));
    }
}

/// The outline of a Prism: points in the x-z plane, as many as its spline needs, and every
/// loop closed.
scene::Shape Interpreter::prismShape(ObjectBuilder& b) {
    scene::PrismShape s;
    const std::vector<Value>& points = *b.get("points")->list;
    for (size_t i = 0; i < points.size(); ++i) {
        const double y = points[i].v[1];
        if (y != 0) {
            fail(b.whereItem("points", i),
                 fmt::format("a Prism's points are its outline in the x-z plane: point {} has "
                             "y = {:g}, not 0",
                             i + 1, y));
        }
        s.points.push_back({points[i].v[0], points[i].v[2]});
    }
    s.spline = splineKind(b, "spline");
    s.conic = b.lowerText("sweep") == "conic";
    s.from = b.number("from", s.from);
    s.to = b.number("to", s.to);
    s.open = b.flag("open", s.open);
    checkPointCount(b, s.spline, scene::minimumLoopPoints(s.spline));
    const std::ptrdiff_t unclosed = scene::curveLoops(s.points, s.spline).unclosedFrom;
    if (unclosed >= 0) {
        const bool control =
            s.spline == scene::SplineKind::Quadratic || s.spline == scene::SplineKind::Cubic;
        fail(b.whereItem("points", static_cast<size_t>(unclosed)),
             fmt::format(
                 "the outline of this Prism does not close: the loop from point {} never "
                 "comes back to {}",
                 unclosed + 1,
                 control ? fmt::format("point {}, its first after the control point", unclosed + 2)
                         : "its first point"));
    }
    return s;
}

std::vector<glm::dvec2> Interpreter::pointsInXY(ObjectBuilder& b, std::string_view what) {
    std::vector<glm::dvec2> out;
    const std::vector<Value>& points = *b.get("points")->list;
    for (size_t i = 0; i < points.size(); ++i) {
        const Value& p = points[i];
        if (p.v[2] != 0) {
            fail(b.whereItem("points", i),
                 fmt::format("{}: point {} has z = {:g}, not 0", what, i + 1, p.v[2]));
        }
        out.push_back({p.v[0], p.v[1]});
    }
    return out;
}

/// The points of a Sor, as POV-Ray checks them: (radius, height) with z 0, at least four,
/// no radius negative, heights rising from the second point to the last but one, and the
/// first and last not level with the points two along, whose slopes they set.
scene::Shape Interpreter::sorShape(ObjectBuilder& b) {
    scene::SorShape s;
    s.open = b.flag("open", s.open);
    const std::vector<Value>& points = *b.get("points")->list;
    if (points.size() < 4)
        fail(b.where("points"),
             fmt::format("a Sor needs at least 4 points, not {}", points.size()));
    s.points = pointsInXY(b, "a Sor's points are (radius, height) in the x-y plane");
    for (size_t i = 0; i < points.size(); ++i) {
        const Value& p = points[i];
        if (p.v[0] < 0) {
            fail(
                b.whereItem("points", i),
                fmt::format("point {} of this Sor has a negative radius, x = {:g}", i + 1, p.v[0]));
        }
    }
    const size_t n = s.points.size();
    for (size_t i = 2; i + 1 < n; ++i) {
        if (!(s.points[i].y > s.points[i - 1].y)) {
            fail(b.whereItem("points", i),
                 fmt::format("the heights of a Sor must rise from its second point to its last but "
                             "one: point {} (y = {:g}) is not above point {} (y = {:g})",
                             i + 1, s.points[i].y, i, s.points[i - 1].y));
        }
    }
    for (auto [end, next] : {std::pair{size_t{0}, size_t{2}}, {n - 1, n - 3}}) {
        if (s.points[end].y == s.points[next].y) {
            fail(b.whereItem("points", end),
                 fmt::format("point {} of this Sor is level with point {}, so the slope at point "
                             "{} between them is undefined",
                             end + 1, next + 1, (end + next) / 2 + 1));
        }
    }
    return s;
}

/// The points of a Lathe, as POV-Ray checks them: (x, y) with z 0, as many as the spline
/// needs, and no point on the curve left of the axis.
scene::Shape Interpreter::latheShape(ObjectBuilder& b) {
    scene::LatheShape s;
    s.spline = splineKind(b, "spline");
    const std::vector<Value>& points = *b.get("points")->list;
    checkPointCount(b, s.spline, scene::minimumCurvePoints(s.spline));
    s.points = pointsInXY(b, "a Lathe's points are its curve in the x-y plane");
    for (size_t i = 0; i < points.size(); ++i) {
        const Value& p = points[i];
        if (p.v[0] < 0 && scene::isOnCurve(i, points.size(), s.spline)) {
            fail(b.whereItem("points", i),
                 fmt::format("point {} of this Lathe is left of the y axis, x = {:g}; the curve's "
                             "x is the distance from the axis",
                             i + 1, p.v[0]));
        }
    }
    return s;
}

/// The points and radii of a SphereSweep, as POV-Ray checks them: a radius for each point,
/// none negative, and as many points as the spline needs.
scene::Shape Interpreter::sphereSweepShape(ObjectBuilder& b) {
    scene::SphereSweepShape s;
    s.spline = splineKind(b, "spline");
    checkPointCount(b, s.spline, s.spline == scene::SplineKind::Linear ? 2 : 4);
    const std::vector<Value>& points = *b.get("points")->list;
    const std::vector<Value>& radii = *b.get("radii")->list;
    if (radii.size() != points.size()) {
        fail(b.where("radii"),
             fmt::format("a SphereSweep takes one radius a point: {} points, {} {}",
                         points.size(), radii.size(), radii.size() == 1 ? "radius" : "radii"));
    }
    for (size_t i = 0; i < points.size(); ++i) {
        s.points.push_back({points[i].v[0], points[i].v[1], points[i].v[2]});
        s.radii.push_back(radii[i].asDouble());
        if (s.radii.back() < 0) {
            fail(b.whereItem("radii", i),
                 fmt::format("radius {} of this SphereSweep is negative ({:g})", i + 1,
                             s.radii.back()));
        }
    }
    return s;
}

} // namespace crt::lang
