// Ray queries against the render scene: nearest hit, CSG crossing lists, surface details.
#include "tracer/render_scene.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

bool insideOf(CsgNodeKind kind, bool left, bool right) {
    switch (kind) {
    case CsgNodeKind::Union:
    case CsgNodeKind::Merge: return left || right;
    case CsgNodeKind::Difference: return left && !right;
    case CsgNodeKind::Intersection: return left && right;
    case CsgNodeKind::Leaf:
    case CsgNodeKind::Inverse:
    case CsgNodeKind::Clip: break; // none of these reaches the general merge
    }
    return left;
}

} // namespace

CsgRay::CsgRay(const Ray& r, const BoxRay& b)
    : ray(r), boxRay(b),
      lineScale(std::max({std::abs(r.origin.x), std::abs(r.origin.y), std::abs(r.origin.z)}) /
                std::max({std::abs(r.dir.x), std::abs(r.dir.y), std::abs(r.dir.z)})) {}

bool RenderScene::csgCrossings(int32_t nodeIndex, const CsgRay& q, QueryScratch& scratch, RayStats& stats) const {
    const CsgTreeNode& node = csgNodes[nodeIndex];
    std::vector<CsgCrossing>& out = scratch.csg;

    if (node.kind != CsgNodeKind::Leaf && convexCrossings(nodeIndex, q, scratch, stats)) return false;
    if (node.kind == CsgNodeKind::Leaf) {
        const Primitive& p = primitives[node.primitive];
        CrossingList list;
        ++stats.intersectionTests;
        inObjectSpace(p, q.ray, [&](const Ray& r) { crossLine(p.geometry, r, list); });
        bool inside = list.startsInside;
        for (int i = 0; i < list.count; ++i) {
            inside = !inside;
            out.push_back({list[i].t, node.primitive, list[i].part, inside, false});
        }
        return list.startsInside;
    }

    // An operand whose bounds the line misses has no crossings and the line is outside it.
    auto operand = [&](int32_t child) {
        const CsgTreeNode& c = csgNodes[child];
        if (c.testBounds && !q.boxRay.hits(c.bounds, -kInfinity, kInfinity)) return false;
        return csgCrossings(child, q, scratch, stats);
    };
    if (node.kind == CsgNodeKind::Inverse) {
        // The same surface, bounding the outside: every crossing enters where it left.
        if (node.left < 0) return true;
        const size_t start = out.size();
        const bool inChild = operand(node.left);
        for (size_t k = start; k < out.size(); ++k) {
            out[k].insideAfter = !out[k].insideAfter;
            out[k].flipNormal = !out[k].flipNormal;
        }
        return !inChild;
    }
    if (node.kind == CsgNodeKind::Clip) {
        // The left child's crossings where the line is inside the right one; the right
        // child's own surfaces are not drawn. The result is a surface: never inside.
        const size_t start = out.size();
        operand(node.left);
        const size_t rightStart = out.size();
        bool inRight = operand(node.right);
        size_t kept = start;
        for (size_t i = start, j = rightStart; i < rightStart; ++i) {
            for (; j < out.size() && out[j].t < out[i].t; ++j) inRight = out[j].insideAfter;
            if (inRight) out[kept++] = out[i];
        }
        out.resize(kept);
        return false;
    }
    size_t leftStart = out.size();
    bool inLeft = operand(node.left);
    size_t rightStart = out.size();
    // A difference or intersection whose left operand the line never enters is empty on
    // it: the right operand need not be asked (a carving tool the ray only meets outside).
    const bool joins = node.kind == CsgNodeKind::Union || node.kind == CsgNodeKind::Merge;
    if (!joins && rightStart == leftStart && !inLeft) return false;
    bool inRight = operand(node.right);
    size_t rightEnd = out.size();
    bool state = insideOf(node.kind, inLeft, inRight);
    bool startsInside = state;

    size_t i = leftStart, j = rightStart;
    while (i < rightStart || j < rightEnd) {
        double t = std::min(i < rightStart ? out[i].t : kInfinity, j < rightEnd ? out[j].t : kInfinity);
        double limit = t + q.coincidence(t);
        size_t groupLeft = i, groupRight = j;
        bool leftBefore = inLeft;
        while (i < rightStart && out[i].t <= limit) inLeft = out[i++].insideAfter;
        while (j < rightEnd && out[j].t <= limit) inRight = out[j++].insideAfter;
        bool next = insideOf(node.kind, inLeft, inRight);
        if (node.kind == CsgNodeKind::Union) {
            // A union keeps every surface of its operands, interior ones included.
            for (size_t k = groupLeft; k < i; ++k) out.push_back({out[k].t, out[k].primitive, out[k].part, next, out[k].flipNormal});
            for (size_t k = groupRight; k < j; ++k) out.push_back({out[k].t, out[k].primitive, out[k].part, next, out[k].flipNormal});
        } else if (next != state) {
            // The event's face: the left operand's when it changed, else the right one's
            // (a cut face of a difference, which bounds the result from the other side).
            bool fromRight = inLeft == leftBefore;
            CsgCrossing c = fromRight ? out[j - 1] : out[i - 1];
            c.insideAfter = next;
            if (fromRight && node.kind == CsgNodeKind::Difference) c.flipNormal = !c.flipNormal;
            out.push_back(c);
        } else if (node.kind != CsgNodeKind::Merge && inLeft == leftBefore && inLeft &&
                   (node.kind == CsgNodeKind::Intersection) == inRight) {
            // Interior surfaces of a union operand stay visible where the result is solid.
            for (size_t k = groupLeft; k < i; ++k)
                if (out[k].insideAfter) out.push_back({out[k].t, out[k].primitive, out[k].part, next, out[k].flipNormal});
        }
        state = next;
    }
    // Move the result over the operands' lists.
    std::copy(out.begin() + rightEnd, out.end(), out.begin() + leftStart);
    out.resize(leftStart + (out.size() - rightEnd));
    return startsInside;
}

bool RenderScene::csgMayCross(int32_t root, const BoxRay& boxRay, double tMax) const {
    // In double precision and on (0, tMax), unlike the BVH's outward-rounded float boxes:
    // a ray leaving the surface of a CSG object whose face lies on its bounds (a box with
    // holes) is not sent through the whole tree again.
    const Bounds3& bounds = csgNodes[root].bounds;
    return !bounds.finite() || boxRay.hits(bounds, 0.0, tMax);
}

bool RenderScene::nearestInObject(int32_t object, const LazyBoxRay& ray, double tMax, Hit& hit,
                                  QueryScratch& scratch, RayStats& stats, Departure departed) const {
    if (isPrimitiveObject(object)) {
        if (departed.skips(object)) return false;
        const Primitive& p = primitives[object];
        ++stats.intersectionTests;
        Crossing c{};
        const bool crosses = inObjectSpace(p, ray.ray(), [&](const Ray& r) {
            return firstCrossingIn(p.geometry, r, 0.0, tMax, c, departed.skippedPart(object));
        });
        if (!crosses) return false;
        hit = {c.t, object, c, false};
        return true;
    }
    if (isInstanceObject(object)) [[unlikely]]
        return nearestInInstance(instanceOfObject(object), ray.ray(), tMax, hit, scratch, stats, departed);
    if (!csgMayCross(csgNodeOfObject(object), ray.box(), tMax)) return false;
    size_t start = scratch.csg.size();
    csgCrossings(csgNodeOfObject(object), CsgRay(ray.ray(), ray.box()), scratch, stats);
    bool found = false;
    for (size_t i = start; i < scratch.csg.size(); ++i) {
        const CsgCrossing& c = scratch.csg[i];
        if (c.t > 0 && c.t < tMax) {
            hit = {c.t, c.primitive, Crossing{c.t, c.part}, c.flipNormal};
            found = true;
            break;
        }
    }
    scratch.csg.resize(start);
    return found;
}

bool RenderScene::nearestInInstance(int32_t i, const Ray& ray, double tMax, Hit& hit, QueryScratch& scratch,
                                    RayStats& stats, Departure departed) const {
    if (!prototypeOf(i).intersect(instanceRay(i, ray), tMax, hit, scratch, stats, departed.inside(i))) return false;
    hit.instance = i;
    return true;
}

bool RenderScene::crossingsInInstance(int32_t i, const Ray& ray, double tMax, QueryScratch& scratch, RayStats& stats,
                                      HitVisitor visit, Departure departed) const {
    auto inInstance = [&](Hit hit) {
        hit.instance = i;
        return visit(hit);
    };
    return prototypeOf(i).forEachCrossing(instanceRay(i, ray), tMax, departed.inside(i), scratch, stats,
                                          HitVisitor(inInstance));
}

bool RenderScene::intersect(const Ray& ray, double tMax, Hit& hit, QueryScratch& scratch, RayStats& stats,
                            Departure departed) const {
    bool found = false;
    double nearest = tMax;
    const int32_t skipped = departed.skippedPrimitive();
    for (const PlaneObject& plane : planes) {
        if (plane.primitive == skipped) continue;
        ++stats.intersectionTests;
        double t = planeCrossing(plane, ray);
        if (t > 0 && t < nearest) {
            hit = {t, plane.primitive, Crossing{t, 0}, false};
            nearest = t;
            found = true;
        }
    }
    const LazyBoxRay lazy(ray);
    for (int32_t object : unbounded) {
        if (nearestInObject(object, lazy, nearest, hit, scratch, stats, departed)) {
            nearest = hit.t;
            found = true;
        }
    }
    bvh.traverse(lazy, nearest, stats, [&](int32_t object) {
        if (nearestInObject(object, lazy, nearest, hit, scratch, stats, departed)) {
            nearest = hit.t;
            found = true;
        }
        return true;
    });
    return found;
}

Departure RenderScene::departedInInstance(const Hit& hit, const SurfaceInteraction& si, const Vec3& dir) const {
    // In the prototype's space the ray and the normal keep the sign of their dot product.
    Hit inner = hit;
    inner.instance = -1;
    Departure departed = prototypeOf(hit.instance).departedPrimitive(inner, si, dir);
    if (departed.primitive >= 0) departed.instance = hit.instance;
    return departed;
}

Departure RenderScene::departedPrimitive(const Hit& hit, const SurfaceInteraction& si, const Vec3& dir) const {
    if (hit.instance >= 0) [[unlikely]]
        return departedInInstance(hit, si, dir);
    // A face a CSG difference turned inside out: its normal points into the primitive.
    if (hit.primitive < 0 || hit.flipNormal) return {};
    // A face's plane or a convex solid's tangent plane has the whole primitive on one side;
    // the ray starts beyond it and moves away.
    const Geometry& geometry = primitives[hit.primitive].geometry;
    if (isFlat(geometry) || (isBoundedConvex(geometry) && glm::dot(dir, si.normal) > 0)) return {hit.primitive};
    if (holds<MeshGeometry>(geometry)) return {hit.primitive, hit.crossing.part};
    return {};
}

uint64_t RenderScene::storedPrimitives() const {
    uint64_t stored = primitives.size() + instances.size();
    for (const auto& mesh : meshes) stored += mesh->data().triangles.size();
    for (const auto& prototype : prototypes) stored += prototype->storedPrimitives();
    return stored;
}

uint64_t RenderScene::byteSize() const {
    auto bytes = [](const auto& v) { return uint64_t(v.capacity()) * sizeof(v[0]); };
    uint64_t total = sizeof(RenderScene) + bytes(primitives) + bytes(primitiveEntities) + bytes(transforms) +
                     bytes(csgNodes) + bytes(meshes) + bytes(materials) + bytes(blends) + bytes(prototypes) +
                     bytes(instances) + bytes(unbounded) + bytes(planes) + bvh.byteSize();
    for (const Primitive& p : primitives) total += outOfLineBytes(p.geometry);
    for (const auto& mesh : meshes) total += mesh->byteSize();
    for (const auto& prototype : prototypes) total += prototype->byteSize();
    return total;
}

int32_t RenderScene::instanceMaterial(const Hit& hit) const {
    const int32_t own = prototypeOf(hit.instance).primitives[static_cast<size_t>(hit.primitive)].material;
    return own >= 0 ? own : instances[static_cast<size_t>(hit.instance)].material;
}

int32_t RenderScene::entityOf(const Hit& hit) const {
    const RenderScene& owner = hit.instance < 0 ? *this : prototypeOf(hit.instance);
    return owner.primitiveEntities[static_cast<size_t>(hit.primitive)];
}

uint8_t RenderScene::hiddenFrom(const Hit& hit) const {
    auto entry = [](const std::vector<uint8_t>& hidden, int32_t i) -> uint8_t {
        return hidden.empty() ? 0 : hidden[static_cast<size_t>(i)];
    };
    if (hit.instance < 0) return entry(hiddenPrimitives, hit.primitive);
    return entry(hiddenInstances, hit.instance) | entry(prototypeOf(hit.instance).hiddenPrimitives, hit.primitive);
}

bool RenderScene::intersectUnhidden(Ray& ray, uint8_t unseen, Hit& hit, double& skipped, QueryScratch& scratch,
                                    RayStats& stats, Departure departed) const {
    skipped = 0;
    // Each crossing moves the ray on; the bound only guards against a surface that rounding
    // keeps in front of it.
    constexpr int kMostCrossings = 4096;
    for (int crossings = 0;; ++crossings) {
        if (crossings == kMostCrossings || !intersect(ray, kInfinity, hit, scratch, stats, departed)) return false;
        if (!(hiddenFrom(hit) & unseen)) return true;
        const SurfaceInteraction si = interaction(ray, hit);
        skipped += hit.t;
        ray = Ray{offsetRayOrigin(si.point, si.pointError, si.normal, ray.dir), ray.dir, ray.time};
        departed = departedPrimitive(hit, si, ray.dir);
        hit = Hit{};
    }
}

bool RenderScene::hidesAnything() const {
    return !hiddenPrimitives.empty() || !hiddenInstances.empty() ||
           std::any_of(prototypes.begin(), prototypes.end(),
                       [](const std::unique_ptr<const RenderScene>& p) { return p->hidesAnything(); });
}

namespace {

/// Moves the surface by toWorld (its object point, uv and material stay as they are).
void moveSurface(const Transform& toWorld, SurfaceInteraction& si) {
    si.pointError = toWorld.pointError(si.point, si.pointError);
    si.point = toWorld.point(si.point);
    si.normal = toWorld.normal(si.normal);
    si.shadingNormal = toWorld.normal(si.shadingNormal);
    si.dpdu = toWorld.vector(si.dpdu);
    si.dpdv = toWorld.vector(si.dpdv);
}

/// Moves a surface found in the object space of the scene's transform `t` (>= 0) into world
/// space, where it is at `time`.
void moveSurface(const RenderScene& scene, int32_t t, double time, SurfaceInteraction& si) {
    if (t < RenderScene::kFirstMovingTransform) [[likely]]
        moveSurface(scene.transforms[static_cast<size_t>(t)].toWorld, si);
    else
        moveSurface(scene.movingTransforms[static_cast<size_t>(t - RenderScene::kFirstMovingTransform)].at(time).toWorld,
                    si);
}

} // namespace

[[gnu::always_inline]] inline SurfaceInteraction RenderScene::primitiveInteraction(const Ray& ray, const Hit& hit,
                                                                                   int32_t material,
                                                                                   const ShadingMaterial& m) const {
    const Primitive& p = primitives[hit.primitive];
    const SurfacePoint sp = inObjectSpace(p, ray, [&](const Ray& r) {
        return surfaceAt(p.geometry, r, hit.crossing, m.readsSurface());
    });
    // Made whole in place: filled with its defaults first, it would be cleared and then
    // written again, for every hit.
    SurfaceInteraction si{.point = sp.point,
                          .pointError = sp.pointError,
                          .normal = sp.normal,
                          .shadingNormal = sp.shadingNormal,
                          .objectPoint = sp.point,
                          .uv = sp.uv,
                          .mappingAxis = m.readsSurface() ? mappingAxis(p.geometry) : MappingAxis{},
                          .dpdu = sp.dpdu,
                          .dpdv = sp.dpdv,
                          .material = material,
                          .solid = isSolid(p.geometry)};
    if (p.transform >= 0) moveSurface(*this, p.transform, ray.time, si);
    if (hit.flipNormal) {
        si.normal = -si.normal;
        si.shadingNormal = -si.shadingNormal;
    }
    return si;
}

SurfaceInteraction RenderScene::interaction(const Ray& ray, const Hit& hit) const {
    const int32_t material = materialOf(hit);
    const ShadingMaterial& m = materials[static_cast<size_t>(material)];
    if (hit.instance < 0) [[likely]]
        return primitiveInteraction(ray, hit, material, m);
    Hit inner = hit;
    inner.instance = -1;
    SurfaceInteraction si =
        prototypeOf(hit.instance).primitiveInteraction(instanceRay(hit.instance, ray), inner, material, m);
    const int32_t transform = instances[static_cast<size_t>(hit.instance)].transform;
    if (transform >= 0) moveSurface(*this, transform, ray.time, si);
    return si;
}


} // namespace crt::tracer
