// The scene as the renderer sees it: primitives with transforms and materials, CSG trees,
// and an acceleration structure, built once from a SceneDesc.
#pragma once

#include "tracer/bvh.hpp"
#include "tracer/geometry/geometry.hpp"
#include "scene/scene_desc.hpp"
#include "tracer/stats.hpp"
#include "tracer/motion.hpp"
#include "tracer/transform.hpp"

#include <memory>
#include <string>
#include <vector>

namespace crt::tracer {

/// A primitive placed in the world: its geometry in object space, the transforms between
/// object and world space (index into RenderScene::transforms; -1 = identity) and its material.
struct Primitive {
    Geometry geometry;
    int32_t transform = -1;
    int32_t material = 0;
};

/// Merge: a union that keeps only its outer surface. Inverse: the complement of `left`
/// (everything when left is -1, the inverse of nothing).
/// Clip: the left child's crossings where the line is inside the right child (clipped_by).
enum class CsgNodeKind : uint8_t { Leaf, Union, Difference, Intersection, Merge, Inverse, Clip };

/// A node of a flattened CSG tree; a leaf refers to a primitive.
struct CsgTreeNode {
    CsgNodeKind kind = CsgNodeKind::Leaf;
    int32_t left = -1, right = -1; ///< children (node indices) of an operator
    int32_t primitive = -1;        ///< leaf
    Bounds3 bounds;                ///< world space; everything() when unbounded
    /// Whether queries test `bounds` before asking the node: not for leaves whose own
    /// crossing test costs about as much as the box test, nor for a difference (its bounds
    /// are its left operand's, which that operand tests itself).
    bool testBounds = false;
    /// A bounded convex solid: a sphere, box, capped cylinder or cone, or an intersection of
    /// such. The line crosses it at most twice, so it is evaluated as one interval.
    bool convex = false;
};

/// A world ray prepared for CSG queries.
struct CsgRay {
    const Ray& ray;
    const BoxRay& boxRay;
    /// Crossings closer than this (in ray units) are one event: coincident faces of two
    /// operands, computed through different transforms, differ by rounding only, and treating
    /// them apart would leave slivers ("speckles") of the face that should vanish. Rounding
    /// grows with the line's scale (|t| and the origin's distance), a few ulps each; the
    /// window is thousands of ulps of it, yet still far below any solid a scene means: a pane
    /// 2e-4 thick a million units from the origin keeps both faces.
    double coincidence(double t) const { return 1e-12 * (std::abs(t) + lineScale); }
    double lineScale; ///< max |origin component| / max |direction component|

    CsgRay(const Ray& r, const BoxRay& b);
};

/// A crossing of a world ray with a CSG tree's surface.
struct CsgCrossing {
    double t;
    int32_t primitive;
    uint32_t part;
    bool insideAfter; ///< whether the line is inside the node's solid after this crossing
    bool flipNormal;  ///< the face bounds the result from the other side (a cut face)
};

/// Where a line enters and leaves a convex CSG node (when not `empty`).
struct ConvexSpan {
    bool empty = true;
    CsgCrossing enter, exit;
};

/// What a ray hit: enough to compute the surface later, only for the hit that wins.
struct Hit {
    double t = kInfinity;
    int32_t primitive = -1; ///< of the instance's prototype when `instance` >= 0
    Crossing crossing{};
    bool flipNormal = false;
    int32_t instance = -1;
};

/// The surface at a hit, in world space.
struct SurfaceInteraction {
    Vec3 point{0.0};
    Vec3 pointError{0.0};
    Vec3 normal{0, 1, 0};        ///< geometric, unit, outward for solids (cut faces flipped)
    Vec3 shadingNormal{0, 1, 0}; ///< same orientation as normal
    Vec3 objectPoint{0.0};       ///< in the primitive's object space (textures)
    Vec2 uv{0.0};                ///< (0, 0) unless the material has a texture or bump
    MappingAxis mappingAxis;     ///< the primitive's, where uv is set
    Vec3 dpdu{0.0}, dpdv{0.0};   ///< world-space ∂point/∂u, ∂point/∂v, where uv is set
    int32_t material = 0;
    bool solid = false;
};

/// A plain plane in world space: tested inline by every ray, without the general dispatch
/// (scenes such as rooms have several, and every ray meets them).
struct PlaneObject {
    Vec3 normal;
    double offset; ///< normal · (a point of the plane)
    int32_t primitive;
};

/// What a ray leaving a surface cannot meet again, so that queries need not test it
/// (RenderScene::departedPrimitive): nothing, a whole primitive, or one face of a mesh; of the
/// scene, or of an instance's prototype.
struct Departure {
    int32_t primitive = -1;
    uint32_t part = kNoPart; ///< the face; kNoPart: the whole primitive
    int32_t instance = -1;   ///< whose prototype holds the primitive; -1: the scene itself

    /// The scene's primitive no query need test at all (-1: none).
    int32_t skippedPrimitive() const { return instance < 0 && part == kNoPart ? primitive : -1; }
    /// Whether primitive `object` (>= 0) of the scene need not be tested at all.
    bool skips(int32_t object) const { return object == skippedPrimitive(); }
    /// The face of primitive `object` of the scene not to test (kNoPart: none).
    uint32_t skippedPart(int32_t object) const {
        return instance < 0 && object == primitive ? part : kNoPart;
    }
    /// What the query of instance i's prototype need not test.
    Departure inside(int32_t i) const { return instance == i ? Departure{primitive, part} : Departure{}; }
};

/// Called with hits until it returns false. A prototype's crossings are visited through one,
/// so that visiting them is not a new template for each level of visitor wrapped around
/// another.
using HitVisitor = FunctionRef<bool(const Hit&)>;

/// A drawing of a shared entity: its prototype (RenderScene::prototypes, built once however
/// often the entity is drawn), moved by `transform`, with `material` for its parts that have
/// none.
struct Instance {
    int32_t prototype = 0;
    int32_t transform = -1;
    int32_t material = 0;
};

/// Per-thread scratch memory, so queries never allocate.
struct QueryScratch {
    std::vector<CsgCrossing> csg;
    std::vector<int32_t> stack;
};

/// A material as shading reads it: its color beside its finish, in one place.
struct ShadingMaterial : scene::FinishDesc {
    scene::Color color = scene::MaterialDesc{}.color;

    /// Whether shading reads the surface's uv (a texture, a bump or the materials of a blend).
    bool readsSurface() const { return texture >= 0 || bump >= 0 || blend >= 0; }
};

/// Built by buildRenderScene; read-only while rendering, shared by every thread.
class RenderScene {
public:
    std::vector<Primitive> primitives;
    /// The SceneDesc entity each primitive was built from (a mesh's for its triangles), for
    /// naming what a ray met (pick.hpp).
    std::vector<int32_t> primitiveEntities;
    std::vector<TransformPair> transforms;
    /// The transforms that change while the shutter is open, numbered from
    /// kFirstMovingTransform where a primitive or an instance names its transform.
    std::vector<MovingTransform> movingTransforms;
    static constexpr int32_t kFirstMovingTransform = 1 << 30;
    std::vector<CsgTreeNode> csgNodes;
    /// The meshes the primitives draw, each once however often it is drawn.
    std::vector<std::shared_ptr<const TriangleMesh>> meshes;
    std::vector<ShadingMaterial> materials;
    std::vector<scene::BlendDesc> blends; ///< of the materials made of others
    std::vector<scene::MediumDesc> media;  ///< what materials fill their solids with
    /// The entities drawn more than once, each built once in its own space, with no materials
    /// of its own (a primitive's material is -1 where the instance gives it), and their
    /// drawings.
    std::vector<std::unique_ptr<const RenderScene>> prototypes;
    std::vector<Instance> instances;

    /// Nearest hit with 0 < t < tMax. `departed` (from departedPrimitive) is not tested.
    bool intersect(const Ray& ray, double tMax, Hit& hit, QueryScratch& scratch, RayStats& stats,
                   Departure departed = {}) const;
    /// Calls visit(hit) for every surface crossing with 0 < t < tMax, in no particular
    /// order, until visit returns false; returns false if stopped early.
    /// `departed` (from departedPrimitive) is not tested.
    template <typename Visit>
    bool forEachCrossing(const Ray& ray, double tMax, Departure departed, QueryScratch& scratch,
                         RayStats& stats, Visit&& visit) const;
    /// What a ray from the hit's point (offset to the side it goes) in direction `dir` cannot
    /// meet again, so that the queries need not test it: a flat primitive, a mesh's face, or a
    /// bounded convex solid the ray leaves outwards. Nothing when it may: the ray enters the
    /// solid, or the primitive is none of these, or the hit is on a face a CSG difference
    /// turned inside out.
    Departure departedPrimitive(const Hit& hit, const SurfaceInteraction& si, const Vec3& dir) const;

    /// The primitives stored: those drawn, each instance as one, and the meshes' triangles and
    /// the prototypes' primitives once each.
    uint64_t storedPrimitives() const;
    /// The bytes the scene holds: its primitives, transforms, CSG trees, BVH and meshes (not
    /// what a shape keeps of its own, such as a prism's outline or a height field's grid).
    uint64_t byteSize() const;

    /// The surface at the hit (uv only where the material reads it).
    SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;
    /// The material at the hit (an index into materials).
    int32_t materialOf(const Hit& hit) const {
        if (hit.instance < 0) [[likely]]
            return primitives[static_cast<size_t>(hit.primitive)].material;
        return instanceMaterial(hit);
    }
    /// The SceneDesc entity the hit primitive was built from.
    int32_t entityOf(const Hit& hit) const;
    /// The prototype instance i draws.
    const RenderScene& prototypeOf(int32_t instance) const {
        return *prototypes[static_cast<size_t>(instances[static_cast<size_t>(instance)].prototype)];
    }

    /// The rays the hit surface is hidden from (scene::HiddenFrom bits; entities' `camera`,
    /// `shadow` and `reflected`). Each list is empty when nothing in it is hidden, else it
    /// holds an entry for every primitive or instance.
    std::vector<uint8_t> hiddenPrimitives, hiddenInstances;
    uint8_t hiddenFrom(const Hit& hit) const;
    /// The nearest hit along `ray` of a surface not hidden from `unseen` (HiddenFrom bits),
    /// crossing those that are: `ray` becomes the ray the hit is on, begun past the crossed
    /// surfaces `skipped` along the original.
    bool intersectUnhidden(Ray& ray, uint8_t unseen, Hit& hit, double& skipped, QueryScratch& scratch,
                           RayStats& stats, Departure departed = {}) const;
    /// Whether anything in the scene or its prototypes is hidden from some rays.
    bool hidesAnything() const;

    /// Objects are what the BVH holds, numbered below WideChild::kMaxItems: a primitive (from
    /// 0), a CSG root (csgObject(node)) or an instance (instanceObject(i)). These are kept
    /// outside it:
    std::vector<int32_t> unbounded; ///< objects kept outside the BVH (unbounded CSG)
    std::vector<PlaneObject> planes; ///< plain planes, also outside the BVH
    Bvh bvh;
    Bounds3 bounds; ///< of the bounded objects

    static constexpr int32_t kFirstCsgObject = 1 << 28;
    static constexpr int32_t kFirstInstanceObject = 1 << 29;
    static bool isPrimitiveObject(int32_t object) { return object < kFirstCsgObject; }
    static int32_t csgObject(int32_t node) { return kFirstCsgObject + node; }
    static int32_t csgNodeOfObject(int32_t object) { return object - kFirstCsgObject; }
    static int32_t instanceObject(int32_t instance) { return kFirstInstanceObject + instance; }
    static bool isInstanceObject(int32_t object) { return object >= kFirstInstanceObject; }
    static int32_t instanceOfObject(int32_t object) { return object - kFirstInstanceObject; }

private:
    bool nearestInObject(int32_t object, const LazyBoxRay& ray, double tMax, Hit& hit, QueryScratch& scratch,
                         RayStats& stats, Departure departed) const;
    template <typename Visit>
    bool crossingsInObject(int32_t object, const LazyBoxRay& ray, double tMax, QueryScratch& scratch,
                           RayStats& stats, Visit& visit, Departure departed) const;
    /// materialOf a hit on an instance: its prototype's primitive's, else the instance's.
    int32_t instanceMaterial(const Hit& hit) const;
    /// departedPrimitive of a hit on an instance.
    Departure departedInInstance(const Hit& hit, const SurfaceInteraction& si, const Vec3& dir) const;
    /// The queries of an instance's prototype, kept out of line: most scenes have none, and
    /// their hot loops stay small.
    [[gnu::noinline]] bool nearestInInstance(int32_t i, const Ray& ray, double tMax, Hit& hit, QueryScratch& scratch,
                                             RayStats& stats, Departure departed) const;
    [[gnu::noinline]] bool crossingsInInstance(int32_t i, const Ray& ray, double tMax, QueryScratch& scratch,
                                               RayStats& stats, HitVisitor visit, Departure departed) const;
    /// The ray in instance i's prototype's space (its t unchanged).
    Ray instanceRay(int32_t i, const Ray& ray) const {
        const int32_t t = instances[static_cast<size_t>(i)].transform;
        return t < 0 ? ray : toObject(t, ray);
    }
    /// The ray in the object space of transform `t` (>= 0), at the ray's time.
    Ray toObject(int32_t t, const Ray& ray) const {
        if (t < kFirstMovingTransform) [[likely]]
            return transforms[static_cast<size_t>(t)].toObject.ray(ray);
        return movingTransforms[static_cast<size_t>(t - kFirstMovingTransform)].at(ray.time).toObject.ray(ray);
    }
    /// The surface at a hit on one of this scene's own primitives, shaded with `material`.
    SurfaceInteraction primitiveInteraction(const Ray& ray, const Hit& hit, int32_t material,
                                            const ShadingMaterial& m) const;
    /// Whether the segment (0, tMax) can meet the CSG tree rooted at `root` (its bounds).
    bool csgMayCross(int32_t root, const BoxRay& boxRay, double tMax) const;
    /// Appends the node's crossings of the whole line to scratch.csg; returns whether the
    /// line starts inside. The caller has tested the node's bounds where that pays.
    bool csgCrossings(int32_t node, const CsgRay& ray, QueryScratch& scratch, RayStats& stats) const;
    /// The crossings of an intersection of convex nodes, or of a difference of two, appended
    /// as csgCrossings appends them but without its general merge. False, with nothing
    /// appended, when the node is of neither kind or two crossings nearly coincide (the
    /// general merge groups those as one event).
    bool convexCrossings(int32_t node, const CsgRay& ray, QueryScratch& scratch, RayStats& stats) const;
    /// A convex node's span; false when two crossings nearly coincide. The caller has tested
    /// the node's bounds where that pays.
    bool convexSpan(int32_t node, const CsgRay& ray, RayStats& stats, ConvexSpan& span) const;
    bool convexOperandSpan(int32_t node, const CsgRay& ray, RayStats& stats, ConvexSpan& span) const;
    /// query(r) for the ray in the primitive's object space: the ray itself where the primitive
    /// has no transform, not a copy (a copy just written is slow to read back whole).
    template <typename Query>
    decltype(auto) inObjectSpace(const Primitive& p, const Ray& ray, Query&& query) const {
        if (p.transform < 0) return query(ray);
        return query(toObject(p.transform, ray));
    }
    friend class RenderSceneBuilder;
};

/// Builds the render scene, its BVH on up to `threads` threads; returns nullptr and sets
/// `error` ("file:line: message") when a mesh cannot be read.
std::unique_ptr<RenderScene> buildRenderScene(const scene::SceneDesc& desc, std::string& error,
                                              unsigned threads = 1);

} // namespace crt::tracer

#include "tracer/render_scene_queries.hpp"
