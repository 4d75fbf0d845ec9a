// Closed outlines in a plane, and which points they enclose.
#include "tracer/geometry/outline.hpp"

#include "tracer/geometry/geometry_math.hpp"

namespace crt::tracer {

Outline::Outline(const std::vector<std::vector<Vec2>>& loops) {
    for (const std::vector<Vec2>& loop : loops) {
        if (loop.size() < 3) continue;
        for (size_t i = 0; i < loop.size(); ++i)
            edges_.push_back({loop[i], loop[(i + 1) % loop.size()]});
    }
}

Outline::Outline(const std::vector<std::vector<scene::CurveSegment>>& loops) {
    for (const std::vector<scene::CurveSegment>& loop : loops)
        for (const scene::CurveSegment& s : loop) addCurve(s);
}

void Outline::addCurve(const scene::CurveSegment& s) {
    if (s.a == Vec2(0.0) && s.b == Vec2(0.0)) {
        edges_.push_back({s.d, s.end});
        return;
    }
    // Split where y turns: at the roots of y' = 3a·u² + 2b·u + c inside (0, 1).
    double turns[2];
    int nTurns = 0;
    double r0, r1;
    if (solveQuadratic(3 * s.a.y, s.b.y, s.c.y, r0, r1)) {
        for (double r : {r0, r1})
            if (r > 0 && r < 1 && (nTurns == 0 || r > turns[0])) turns[nTurns++] = r;
    } else if (s.a.y == 0 && s.b.y != 0) {
        const double r = -s.c.y / (2 * s.b.y);
        if (r > 0 && r < 1) turns[nTurns++] = r;
    }
    double u0 = 0;
    Vec2 a = s.d;
    for (int i = 0; i <= nTurns; ++i) {
        const double u1 = i < nTurns ? turns[i] : 1;
        const Vec2 b = i < nTurns ? s.at(u1) : s.end;
        arcs_.push_back({s, u0, u1, a, b});
        u0 = u1;
        a = b;
    }
}

double Outline::crossingX(const Arc& arc, double y) {
    const double u = bracketedRoot(
        [&](double u) {
            return ValueAndSlope{arc.curve.at(u).y - y, arc.curve.slope(u).y};
        },
        arc.u0, arc.u1, arc.a.y < y);
    return arc.curve.at(u).x;
}

bool Outline::contains(const Vec2& p) const {
    // Crossings of the ray from p toward +x. Each edge counts its lower end and not its upper
    // one, so a ray through a vertex counts the two edges meeting there once between them.
    bool inside = false;
    for (const Edge& e : edges_) {
        if ((e.a.y > p.y) == (e.b.y > p.y)) continue;
        const double x = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
        if (p.x < x) inside = !inside;
    }
    for (const Arc& arc : arcs_) {
        if ((arc.a.y > p.y) == (arc.b.y > p.y)) continue;
        const double x = arc.a.y == p.y ? arc.a.x : arc.b.y == p.y ? arc.b.x : crossingX(arc, p.y);
        if (p.x < x) inside = !inside;
    }
    return inside;
}

} // namespace crt::tracer
