// The surfaces that glow, as lights the path integrator aims at (next-event estimation).
#pragma once

#include "tracer/render_scene.hpp"

#include <vector>

namespace crt::tracer {

/// A point chosen on an emitting surface for a shading point.
struct EmitterSample {
    Vec3 point{0.0};
    Vec3 normal{0, 1, 0}; ///< unit, world space
    Vec3 radiance{0.0};   ///< the emission (two-sided)
    double pdf = 0;       ///< solid angle at the shading point, the choice of emitter included
};

/// The primitives whose material emits and whose shape can be sampled by area: spheres,
/// discs, quads, triangles and each face of a mesh, drawn directly and standing still (not
/// through an instance, a CSG tree, a material blend or a transform that moves while the
/// shutter is open; those are found by the paths' own bounces).
/// One is chosen by power (emission × area), then a point on it: on a sphere (moved by a
/// similarity at most) seen from outside, uniformly in the cone of directions it fills;
/// elsewhere uniformly by area.
class Emitters {
public:
    explicit Emitters(const RenderScene& scene);

    bool empty() const { return entries_.empty(); }
    size_t size() const { return entries_.size(); }
    /// A point on an emitter for the shading point `from`; false when none can be had.
    bool sample(const Vec3& from, double pick, const Vec2& u, EmitterSample& out) const;
    /// The density sample() has of choosing the hit's point from `from` (solid angle); 0 for a
    /// surface it never chooses.
    double pdf(const Hit& hit, const Vec3& from, const Vec3& point, const Vec3& normal) const;

private:
    struct Entry {
        int32_t primitive;
        uint32_t face;     ///< a mesh's triangle
        double objectArea; ///< before the primitive's transform
        /// A sphere sampled by its cone of directions: its centre and radius in world space
        /// (radius 0 for every other entry).
        Vec3 center{0.0};
        double radius = 0;
    };
    /// Makes a sphere's entry sampled by its cone, where its transform keeps it a sphere.
    void placeCone(Entry& e, const SphereGeometry& sphere) const;
    /// The solid angle a sphere entry fills seen from `from`, or 0 from inside it.
    static double coneSolidAngle(const Entry& e, const Vec3& from);
    /// The area density of the entry's surface at a point of world normal `normal`.
    double areaDensity(const Entry& e, const Vec3& normal) const;
    /// The density of choosing `point` (normal `normal`) on entry `index` by area, in solid
    /// angle at `from`, the choice of the entry included; 0 edge-on.
    double areaSolidAngleDensity(size_t index, const Vec3& from, const Vec3& point, const Vec3& normal) const;
    double chance(size_t entry) const { return cumulative_[entry + 1] - cumulative_[entry]; }

    const RenderScene& scene_;
    std::vector<Entry> entries_;
    std::vector<double> cumulative_;       ///< of the chances, from 0 to 1
    std::vector<int32_t> firstEntryOf_;    ///< by primitive: its first entry, or -1
};

} // namespace crt::tracer
