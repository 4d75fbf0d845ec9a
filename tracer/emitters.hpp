// The surfaces that glow, as lights the path integrator aims at (next-event estimation).
#pragma once

#include "tracer/distribution.hpp"
#include "tracer/render_scene.hpp"

#include <unordered_map>
#include <vector>

namespace crt::tracer {

/// A point chosen on an emitting surface for a shading point.
struct EmitterSample {
    Vec3 point{0.0};
    Vec3 normal{0, 1, 0}; ///< unit, world space
    Vec3 radiance{0.0};   ///< the emission (two-sided)
    double pdf = 0;       ///< solid angle at the shading point, the choice of emitter included
    /// Set for a CSG operand's surface, which the tree may have carved away at the point: the
    /// caller sees whether a ray meets it there (a Hit of `primitive` and `instance`).
    bool mayBeCarved = false;
    int32_t primitive = -1, instance = -1;
};

/// The primitives whose material emits and whose shape can be sampled by area: spheres,
/// discs, quads, triangles and meshes, drawn directly, as CSG operands or inside the drawings
/// of a shared entity (instances), and standing still (not with a material blend, nor with a
/// transform that moves while the shutter is open; those are found by the paths' own
/// bounces).
/// One is chosen by power (emission × area), then a point on it: on a sphere (moved by a
/// similarity at most) seen from outside, uniformly in the cone of directions it fills;
/// elsewhere uniformly by area (a mesh: a face by its area, then a point on it).
class Emitters {
public:
    explicit Emitters(const RenderScene& scene);

    bool empty() const { return sources_.empty(); }
    size_t size() const { return sources_.size(); }
    /// A point on an emitter for the shading point `from`; false when none can be had.
    bool sample(const Vec3& from, double pick, const Vec2& u, EmitterSample& out) const;
    /// The density sample() has of choosing the hit's point from `from` (solid angle); 0 for a
    /// surface it never chooses.
    double pdf(const Hit& hit, const Vec3& from, const Vec3& point, const Vec3& normal) const;

private:
    /// One emitting primitive, of the scene or of an instance's prototype, with what sampling
    /// reads of it looked up once.
    struct Source {
        int32_t instance = -1; ///< -1: the scene's own primitive
        int32_t primitive = -1;
        const Geometry* geometry = nullptr;
        const TransformPair* shape = nullptr;   ///< the primitive's transform, or null
        const TransformPair* drawing = nullptr; ///< the instance's transform, or null
        int32_t faces = -1;    ///< a mesh's faces by their areas (faceTables_), or -1
        bool mayBeCarved = false;
        double objectArea = 0; ///< before any transform
        Vec3 radiance{0.0};
        /// A sphere sampled by its cone of directions: its centre and radius in world space
        /// (radius 0 for every other source).
        Vec3 center{0.0};
        double radius = 0;
    };
    /// A primitive of a scene that may glow: its own material does, or it has none and takes
    /// the drawing's.
    struct Candidate {
        int32_t primitive;
        bool inCsg;
    };
    std::vector<Candidate> candidatesOf(const RenderScene& owner) const;
    /// The face table of `mesh` (made on its first use), and its area.
    int32_t faceTableOf(const TriangleMesh& mesh, double& area);
    /// The sources of the candidates of `owner`, the scene's own or drawn by `instance`.
    void addSources(const RenderScene& owner, int32_t instance, const std::vector<Candidate>& candidates,
                    std::vector<double>& power);
    /// Makes a sphere's source sampled by its cone, where its transforms keep it a sphere.
    static void placeCone(Source& s, const SphereGeometry& sphere);
    /// The solid angle a sphere source fills seen from `from`, or 0 from inside it.
    static double coneSolidAngle(const Source& s, const Vec3& from);
    /// The area density of the source's surface at a world point of normal `normal`.
    static double areaDensity(const Source& s, const Vec3& normal);
    /// The density of choosing `point` (normal `normal`) on source `index` by area, in solid
    /// angle at `from`, the choice of the source included; 0 edge-on.
    double areaSolidAngleDensity(size_t index, const Vec3& from, const Vec3& point, const Vec3& normal) const;
    /// A point uniform by area on the source, in world space.
    AreaSample pointOn(const Source& s, const Vec2& u) const;
    double chance(size_t source) const { return cumulative_[source + 1] - cumulative_[source]; }
    static uint64_t key(int32_t instance, int32_t primitive) {
        return (static_cast<uint64_t>(static_cast<uint32_t>(instance + 1)) << 32) | static_cast<uint32_t>(primitive);
    }

    const RenderScene& scene_;
    std::vector<Source> sources_;
    std::vector<double> cumulative_; ///< of the chances, from 0 to 1
    /// Each mesh's faces by their areas, shared by every drawing of the mesh.
    std::vector<Distribution1D> faceTables_;
    std::unordered_map<const TriangleMesh*, int32_t> faceTableOfMesh_;
    /// The source of each of the scene's own primitives (-1: none; empty when none is one), and
    /// of a part of a drawing, by key(instance, primitive): a vector would hold an entry for
    /// every primitive of every drawing.
    std::vector<int32_t> sourceOfPrimitive_;
    std::unordered_map<uint64_t, int32_t> sourceOfInstancePart_;
};

} // namespace crt::tracer
