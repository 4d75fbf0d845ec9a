// The templated crossing queries of RenderScene (included by render_scene.hpp).
#pragma once

namespace crt::tracer {

/// Where the ray crosses the plane (infinity when parallel).
inline double planeCrossing(const PlaneObject& plane, const Ray& ray) {
    double along = glm::dot(plane.normal, ray.dir);
    return along != 0 ? (plane.offset - glm::dot(plane.normal, ray.origin)) / along : kInfinity;
}

template <typename Visit>
bool RenderScene::crossingsInObject(int32_t object, const LazyBoxRay& ray, double tMax, QueryScratch& scratch,
                                    RayStats& stats, Visit& visit, Departure departed) const {
    if (isPrimitiveObject(object)) {
        if (departed.skips(object)) return true;
        const Primitive& p = primitives[object];
        ++stats.intersectionTests;
        auto hit = [&](const Crossing& c) { return visit(Hit{c.t, object, c, false}); };
        return inObjectSpace(p, ray.ray(), [&](const Ray& r) {
            return crossingsIn(p.geometry, r, 0.0, tMax, hit, departed.skippedPart(object));
        });
    }
    if (isInstanceObject(object)) [[unlikely]]
        return crossingsInInstance(instanceOfObject(object), ray.ray(), tMax, scratch, stats, HitVisitor(visit),
                                   departed);
    if (!csgMayCross(csgNodeOfObject(object), ray.box(), tMax)) return true;
    size_t start = scratch.csg.size();
    csgCrossings(csgNodeOfObject(object), CsgRay(ray.ray(), ray.box()), scratch, stats);
    bool keepGoing = true;
    for (size_t i = start; i < scratch.csg.size() && keepGoing; ++i) {
        const CsgCrossing& c = scratch.csg[i];
        if (c.t > 0 && c.t < tMax)
            keepGoing = visit(Hit{c.t, c.primitive, Crossing{c.t, c.part}, c.flipNormal});
    }
    scratch.csg.resize(start);
    return keepGoing;
}

template <typename Visit>
bool RenderScene::forEachCrossing(const Ray& ray, double tMax, Departure departed, QueryScratch& scratch,
                                  RayStats& stats, Visit&& visit) const {
    const int32_t skipped = departed.skippedPrimitive();
    for (const PlaneObject& plane : planes) {
        if (plane.primitive == skipped) continue;
        ++stats.intersectionTests;
        double t = planeCrossing(plane, ray);
        if (t > 0 && t < tMax && !visit(Hit{t, plane.primitive, Crossing{t, 0}, false}))
            return false;
    }
    const LazyBoxRay lazy(ray);
    for (int32_t object : unbounded)
        if (!crossingsInObject(object, lazy, tMax, scratch, stats, visit, departed)) return false;
    return bvh.traverse(lazy, tMax, stats, [&](int32_t object) {
        return crossingsInObject(object, lazy, tMax, scratch, stats, visit, departed);
    });
}

} // namespace crt::tracer
