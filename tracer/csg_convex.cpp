// CSG of convex solids without the general merge: an intersection of convex solids is
// convex, so the line crosses it at most twice, and a difference of two crosses at most
// four times. Most CSG in scenes (lenses, carved blocks) is of this kind.
//
// The results equal the general merge's (render_scene.cpp) whenever no two crossings lie
// within its coincidence tolerance; otherwise these functions decline and the general merge,
// which groups such crossings as one event, runs instead.
#include "tracer/render_scene.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

/// Whether the general merge would see crossings x ≤ y as two events.
bool apart(const CsgRay& q, double x, double y) {
    return y > x + q.coincidence(x);
}

/// The same for the crossings of two spans, a0 ≤ a1 and b0 ≤ b1: each must be apart from
/// the next in their merged order. That order needs no merge: the first is the earlier
/// entry, the last the later exit, and between them lie the later entry and the earlier
/// exit, in either order (minima and maxima, not branches on the ray's data).
bool apart(const CsgRay& q, const ConvexSpan& a, const ConvexSpan& b) {
    const double first = std::min(a.enter.t, b.enter.t), last = std::max(a.exit.t, b.exit.t);
    const double laterEntry = std::max(a.enter.t, b.enter.t), earlierExit = std::min(a.exit.t, b.exit.t);
    const double second = std::min(laterEntry, earlierExit), third = std::max(laterEntry, earlierExit);
    const bool firstApart = apart(q, first, second), middleApart = apart(q, second, third),
               lastApart = apart(q, third, last);
    return firstApart & middleApart & lastApart;
}

/// A crossing of a subtracted solid bounds the difference from the other side.
CsgCrossing cut(CsgCrossing c, bool insideAfter) {
    c.insideAfter = insideAfter;
    c.flipNormal = !c.flipNormal;
    return c;
}

} // namespace

bool RenderScene::convexOperandSpan(int32_t nodeIndex, const CsgRay& q, RayStats& stats, ConvexSpan& span) const {
    const CsgTreeNode& node = csgNodes[nodeIndex];
    if (node.testBounds && !q.boxRay.hits(node.bounds, -kInfinity, kInfinity)) {
        span.empty = true;
        return true;
    }
    return convexSpan(nodeIndex, q, stats, span);
}

bool RenderScene::convexSpan(int32_t nodeIndex, const CsgRay& q, RayStats& stats, ConvexSpan& span) const {
    const CsgTreeNode& node = csgNodes[nodeIndex];
    if (node.kind == CsgNodeKind::Leaf) {
        const Primitive& p = primitives[node.primitive];
        CrossingList list;
        ++stats.intersectionTests;
        inObjectSpace(p, q.ray, [&](const Ray& r) { crossLine(p.geometry, r, list); });
        if (list.startsInside || (list.count != 0 && list.count != 2)) return false;
        span.empty = list.count == 0;
        if (!span.empty) {
            span.enter = {list[0].t, node.primitive, list[0].part, true, false};
            span.exit = {list[1].t, node.primitive, list[1].part, false, false};
        }
        return true;
    }
    // An intersection: from the later entry to the earlier exit.
    ConvexSpan a, b;
    span.empty = true;
    if (!convexOperandSpan(node.left, q, stats, a)) return false;
    if (a.empty) return true;
    if (!convexOperandSpan(node.right, q, stats, b)) return false;
    if (b.empty) return true;
    if (!apart(q, a, b)) return false;
    span.enter = a.enter.t > b.enter.t ? a.enter : b.enter;
    span.exit = a.exit.t < b.exit.t ? a.exit : b.exit;
    span.empty = !(span.enter.t < span.exit.t);
    return true;
}

bool RenderScene::convexCrossings(int32_t nodeIndex, const CsgRay& q, QueryScratch& scratch, RayStats& stats) const {
    const CsgTreeNode& node = csgNodes[nodeIndex];
    std::vector<CsgCrossing>& out = scratch.csg;
    if (node.convex) {
        ConvexSpan span;
        if (!convexSpan(nodeIndex, q, stats, span)) return false;
        if (!span.empty) {
            out.push_back(span.enter);
            out.push_back(span.exit);
        }
        return true;
    }
    if (node.kind != CsgNodeKind::Difference || !csgNodes[node.left].convex || !csgNodes[node.right].convex)
        return false;
    ConvexSpan a, b;
    if (!convexOperandSpan(node.left, q, stats, a)) return false;
    if (a.empty) return true;
    if (!convexOperandSpan(node.right, q, stats, b)) return false;
    if (b.empty) {
        if (!apart(q, a.enter.t, a.exit.t)) return false;
        out.push_back(a.enter);
        out.push_back(a.exit);
        return true;
    }
    if (!apart(q, a, b)) return false;
    // What is left of [a.enter, a.exit] outside (b.enter, b.exit): up to two pieces.
    if (a.enter.t < b.enter.t) {
        out.push_back(a.enter);
        if (a.exit.t < b.enter.t) {
            out.push_back(a.exit);
            return true;
        }
        out.push_back(cut(b.enter, false));
    }
    if (b.exit.t < a.exit.t) {
        out.push_back(a.enter.t < b.exit.t ? cut(b.exit, true) : a.enter);
        out.push_back(a.exit);
    }
    return true;
}

} // namespace crt::tracer
