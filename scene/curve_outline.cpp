// Curves as POV-Ray's prism and lathe read their points (see curve_outline.hpp).
#include "scene/curve_outline.hpp"

namespace crt::scene {

using V = glm::dvec2;
using namespace curve_pieces;

size_t minimumLoopPoints(SplineKind kind) {
    switch (kind) {
    case SplineKind::Linear: return 3;
    case SplineKind::Quadratic: return 5;
    case SplineKind::Cubic: return 6;
    case SplineKind::Bezier: return 4;
    case SplineKind::BSpline: return 4;
    }
    return 3;
}

size_t minimumCurvePoints(SplineKind kind) {
    switch (kind) {
    case SplineKind::Linear: return 2;
    case SplineKind::Quadratic: return 3;
    case SplineKind::Cubic: return 4;
    case SplineKind::Bezier: return 4;
    case SplineKind::BSpline: return 4;
    }
    return 2;
}

bool isOnCurve(size_t i, size_t n, SplineKind kind) {
    switch (kind) {
    case SplineKind::Linear: return true;
    case SplineKind::Quadratic: return i > 0;
    case SplineKind::Cubic: return i > 0 && i + 1 < n;
    case SplineKind::Bezier: return i % 4 == 0 || i % 4 == 3;
    case SplineKind::BSpline: return true; // on none, but the curve keeps to their hull
    }
    return true;
}

bool curveEnclosesSolid(const std::vector<CurveSegment>& segments) {
    if (segments.empty()) return false;
    for (size_t i = 1; i < segments.size(); ++i)
        if (segments[i].d != segments[i - 1].end) return false;
    const V start = segments.front().d, end = segments.back().end;
    return end == start || (start.x == 0 && end.x == 0);
}

CurveLoops curveLoops(std::span<const glm::dvec2> p, SplineKind kind) {
    CurveLoops out;
    const size_t n = p.size();
    std::vector<CurveSegment> loop;
    // `start` is the loop's first point as written (a control point for the splines), `first`
    // the point on the curve that closes it.
    size_t start = 0;
    auto close = [&](size_t next) {
        out.loops.push_back(std::move(loop));
        loop.clear();
        start = next;
    };
    switch (kind) {
    case SplineKind::Linear:
        for (size_t i = 0; i + 1 < n; ++i) {
            loop.push_back(line(p[i], p[i + 1]));
            if (p[i + 1] == p[start]) close(++i + 1);
        }
        if (!loop.empty()) {
            loop.push_back(line(p[n - 1], p[start]));
            close(n);
        }
        return out;
    case SplineKind::Quadratic:
        for (size_t i = 0; i + 2 < n; ++i) {
            loop.push_back(quadratic(p[i], p[i + 1], p[i + 2]));
            if (p[i + 2] == p[start + 1]) close((i += 2) + 1);
        }
        break;
    case SplineKind::Cubic:
        for (size_t i = 0; i + 3 < n; ++i) {
            loop.push_back(cubic(p[i], p[i + 1], p[i + 2], p[i + 3]));
            if (p[i + 2] == p[start + 1]) close((i += 3) + 1);
        }
        break;
    case SplineKind::Bezier:
        for (size_t i = 0; i + 3 < n; i += 4) {
            if (!loop.empty() && p[i] != loop.back().end) break; // a gap: not closed
            loop.push_back(bezier(p[i], p[i + 1], p[i + 2], p[i + 3]));
            if (p[i + 3] == p[start]) close(i + 4);
        }
        break;
    case SplineKind::BSpline: break; // not a prism's kind (kLoopSplineKindNames): unclosed
    }
    if (start < n) out.unclosedFrom = static_cast<std::ptrdiff_t>(start);
    return out;
}

} // namespace crt::scene
