// Path tracing (Settings.integrator "path"): light that bounces off every surface, with
// next-event estimation and multiple importance sampling (docs/rendering.md, "Path tracing").
#pragma once

#include "tracer/background.hpp"
#include "tracer/fog.hpp"
#include "tracer/bsdf.hpp"
#include "tracer/emitters.hpp"
#include "tracer/environment_light.hpp"
#include "tracer/integrator.hpp"

#include <glm/mat2x2.hpp>

#include <array>
#include <vector>

namespace crt::tracer {

/// What a camera path first meets that light sampling can reach (not a perfect mirror, nor
/// clear glass, which it follows): the albedo and normal AOVs.
struct FirstSurface {
    Vec3 albedo{0.0}; ///< Bsdf::albedo
    Vec3 normal{0.0}; ///< the shading normal, bumped, facing the ray
    bool found = false;
};

class PathIntegrator {
public:
    /// Reads the scene, lights, background and textures while it lives.
    PathIntegrator(const RenderScene& scene, const scene::SettingsDesc& settings, const std::vector<Light>& lights,
                   const Background& background, const Fog* fog, const std::vector<Texture>& textures);

    /// One path's estimate of the light along a camera ray, and alpha: 0 when the ray meets
    /// nothing and the background is transparent (the colour is then black), else 1.
    /// `first` (optional) gets what the path first meets.
    glm::dvec4 traceCamera(const Ray& ray, bool transparentBackground, TraceContext& context,
                           FirstSurface* first = nullptr) const;

    const Emitters& emitters() const { return emitters_; }

private:
    /// Veach's power heuristic (β = 2): the weight of a sample drawn with density `mine` where
    /// another strategy draws it with density `other`.
    static double powerHeuristic(double mine, double other) {
        const double a = mine * mine, b = other * other;
        return a + b > 0 ? a / (a + b) : 0;
    }
    /// Where a path is: the surface it reached, or the point of a medium it scattered at,
    /// and what it knows of how it got there.
    struct Vertex {
        Hit hit;
        SurfaceInteraction si;
        Vec3 n;                ///< shading normal, facing the incoming ray (bumped)
        double pathLength = 0; ///< from the camera to this point (lights' falloff)
        int bounce = 0;        ///< the path's bounces before it
        bool inMedium = false; ///< a point of a medium the path scattered at (si.point only)
        bool inAir = false;    ///< the path is in no solid here (air)
    };
    /// A path that left a surface point by a lobe light sampling reaches, then crossed only
    /// clear glass (path_caustics.cpp): where it left, and how.
    struct CausticStart {
        Vertex from;
        Vec3 dir{0.0};
        double chance = 0; ///< its density of the direction, times the glass lobes' chances
        int crossings = -1; ///< the glass surfaces crossed since; -1: the path is on no such way
    };
    /// A medium's phase function where a path scatters in it, as light sampling and the
    /// path's next direction read it (a BSDF's evalCos and pdf).
    struct PhaseScatter {
        const Medium& medium;
        Vec3 d; ///< the unit direction the path arrived along
        Vec3 evalCos(const Vec3& wi) const { return Vec3(pdf(wi)); }
        double pdf(const Vec3& wi) const { return medium.phase(glm::dot(wi, d)); }
    };
    struct Path;
    /// Ends a bounce: the next one's numbers, and Russian roulette; false when the path ends.
    bool nextBounce(Path& path, TraceContext& context) const;
    /// What the path meets between its ray's origin and `reach` besides surfaces and media:
    /// area lights, and the absorption of the solid it is in (when it has no medium), or fog.
    void alongSegment(Path& path, double reach, bool inMedium, TraceContext& context) const;
    /// A scattering in `medium` at t along the path's ray: light sampling through the phase
    /// function, and its draw of the next direction; false when the path ends.
    [[gnu::noinline]] bool scatterInMedium(Path& path, const Medium& medium, double t, TraceContext& context) const;
    /// The surface at `v` with `material` of `color`: its emission, light sampling through its
    /// BSDF, and the BSDF's draw of the next direction; false when the path ends.
    bool scatterAtSurface(Path& path, Vertex& v, int32_t material, const Vec3& color, FirstSurface* first,
                          TraceContext& context) const;
    /// The BSDF of material `m` of colour `color` at the surface of `v`, for a ray of
    /// direction `d`; sets v.n.
    Bsdf bsdfAt(Vertex& v, const ShadingMaterial& m, const Vec3& color, const Vec3& d) const;
    /// What a path does in a medium before `reach`: it scatters at t, or passes.
    struct MediumStep {
        bool scattered = false;
        double t = 0;
    };
    /// The plain material the path meets at the hit (one share of a blend, drawn by weight),
    /// or -1 when it passes the surface unbent; `beta` takes the draw's weight.
    int32_t drawMaterial(const SurfaceInteraction& si, Vec3& color, Vec3& beta, TraceContext& context) const;
    /// The light arriving from the lights and emitting surfaces, sent on by the BSDF (or the
    /// phase function) towards the path's previous vertex.
    template <typename Scatter>
    Vec3 directLight(const Vertex& v, const Scatter& scatter, TraceContext& context) const;
    template <typename Scatter>
    Vec3 fromLights(const Vertex& v, const Scatter& scatter, TraceContext& context) const;
    /// The light of the area lights the path's ray meets before `tMax`, weighed against light
    /// sampling's chance of the same path (straight, or solved for through glass).
    Vec3 areaLightsAlong(const Path& path, double tMax, TraceContext& context) const;
    template <typename Scatter>
    Vec3 fromEmitter(const Vertex& v, const Scatter& scatter, TraceContext& context) const;
    template <typename Scatter>
    Vec3 fromEnvironment(const Vertex& v, const Scatter& scatter, TraceContext& context) const;
    /// Where a ray toward `dir` leaves the vertex, and what it cannot meet again.
    Vec3 originToward(const Vertex& v, const Vec3& dir) const;
    Departure departedToward(const Vertex& v, const Vec3& dir) const;
    /// The share of light that passes along the segment (0, tMax) of `ray`: surfaces block it
    /// but for what a colour's alpha lets through unbent and clear boundaries (glass is
    /// reached by the path's own refraction, so it is not counted twice), and the media and
    /// absorbing solids within clear boundaries dim it.
    Vec3 visibility(const Ray& ray, double tMax, Departure departed, TraceContext& context) const;
    /// The reach of a shadow ray toward a point of an emitter (as a share of the way): short
    /// of the emitter's own surface, which the rounding of the point may put a hair in front
    /// of the ray's end.
    static constexpr double kShortOfEmitter = 1 - 1e-7;
    /// Whether the emitter's surface is there at the sampled point, as seen from `from` (a CSG
    /// tree may have carved it away).
    bool emitterSurfaceAt(const EmitterSample& es, const Vec3& from, TraceContext& context) const;

    // Caustics: light through clear glass (path_caustics.cpp).
    /// A ray that left a chain of clear-glass surfaces, and what they did to its light.
    struct ChainRay;
    /// The directions a solve turns among (path_caustics.cpp).
    struct DirectionChart;
    /// A point a chain through glass is to reach: of an emitter, of an area light, or a point
    /// light's position.
    struct ChainTarget {
        Vec3 point;
        Frame frame; ///< its w the normal of the plane the landings are measured on
        int32_t primitive = -1, instance = -1; ///< the emitter's; -1: a light's
        bool bouncesReach = true; ///< whether the paths' bounces meet it too (not a point)
    };
    /// A path from a surface point through clear glass to a target.
    struct Chain {
        Vec3 wi{0.0};         ///< the direction it leaves the surface point in
        Vec3 arrival{0.0};    ///< the unit direction it reaches the target in
        Vec3 throughput{0.0}; ///< the share of the light the glass lets through
        double chance = 0;    ///< the chance that the glass lobes' draws follow it
        double spread = 0;    ///< the target plane's area per solid angle at the surface point
        double length = 0;    ///< from the surface point to the target, along the path
        int crossings = 0;
    };
    /// Finds the clear-glass materials (constructor).
    void prepareCaustics();
    bool isSharpGlass(int32_t material) const {
        return material >= 0 && mixer_.isPlain(material) && sharpGlass_[static_cast<size_t>(material)];
    }
    /// Follows a ray from `from` toward `dir` through `crossings` clear-glass surfaces; false
    /// when it meets anything else first, or one of them does not let it through.
    bool followGlass(const Vertex& from, const Vec3& dir, int crossings, ChainRay& out, TraceContext& context) const;
    /// Where that ray meets the target's plane, from the target (in the frame's u and v).
    bool landing(const Vertex& from, const Vec3& dir, const ChainTarget& target, int crossings, Vec2& miss,
                 ChainRay& ray, TraceContext& context) const;
    /// How the landing follows the direction: its derivatives by the chart's coordinates at
    /// p, where it is `miss`.
    bool landingSlope(const Vertex& from, const DirectionChart& chart, const Vec2& p, const ChainTarget& target,
                      int crossings, const Vec2& miss, glm::dmat2& slope, TraceContext& context) const;
    /// The path of `crossings` glass surfaces from `from` to the target, solved for from the
    /// direction `seed`.
    bool solveFrom(const Vertex& from, const ChainTarget& target, const Vec3& seed, int crossings, Chain& out,
                   TraceContext& context) const;
    /// Where the glass of `hit` stands: the middle of its bounds and its largest half-extent,
    /// in world space; false for an instance's part, or a moving or unbounded primitive.
    bool glassExtent(const Hit& hit, Vec3& middle, double& radius) const;
    /// The paths from `from` through the clear glass the straight line to the target
    /// crosses, solved for from their seeds, each once: how many (none when the line crosses
    /// anything else or nothing). A function of the two points alone, so that paths found
    /// either way agree on it.
    using Chains = std::array<Chain, 8>;
    int glassChainsTo(const Vertex& from, const ChainTarget& target, Chains& found, TraceContext& context) const;
    /// Light sampling's estimate of the light of the sampled emitter point reaching `v`
    /// through the clear glass that hides it from the straight line.
    Vec3 causticFromEmitter(const Vertex& v, const Bsdf& bsdf, const EmitterSample& es,
                            TraceContext& context) const;
    /// The light of a point or spot light reaching `v` through the clear glass that hides it.
    Vec3 causticFromLight(const Vertex& v, const Bsdf& bsdf, const Light& light, TraceContext& context) const;
    /// What lightStrength gives a point light at the end of `chain` (its target on the plane
    /// of normal `planeNormal`) for the point the chain leaves, `pathLength` from the camera:
    /// its strength there, times how the glass spreads or gathers its beam; 0 edge-on.
    static double strengthThrough(const Light& light, const Chain& chain, const Vec3& planeNormal, double pathLength);
    /// Whether light from `light` through glass is solved for: an area light of a fixed plane,
    /// unseen (glass and mirrors show a visible light as its colour, traceCamera's lamp,
    /// which no solve is weighed against).
    static bool solvedThroughGlass(const Light& light) { return light.fixedPlane() && !light.visible(); }
    /// Light sampling's estimate of the light of the sampled point of an area light (of a
    /// fixed plane) reaching `v` through the clear glass that hides it.
    Vec3 causticFromAreaLight(const Vertex& v, const Bsdf& bsdf, const Light& light, const LightSample& ls,
                              TraceContext& context) const;
    /// Notes in `start` the path's bounce at `v` toward `next`: a start, one more crossing of
    /// clear glass, or the end of such a way.
    void noteCausticBounce(CausticStart& start, const Vertex& v, const BsdfSample& next) const;
    /// The weight of the emission at `v`, an emitter the path met after `start`, against
    /// light sampling's chance of the same path through the glass.
    double causticWeight(const CausticStart& start, const Vertex& v, TraceContext& context) const;
    /// The same for an area light (of a fixed plane) the path met at `point`.
    double causticWeight(const CausticStart& start, const Light& light, const Vec3& point,
                         TraceContext& context) const;
    /// The weight of a path that left `start` and met `target`, a point light sampling draws
    /// with density `pointDensity` by area, against light sampling's chance of it.
    double chainWeight(const CausticStart& start, const ChainTarget& target, double pointDensity,
                       TraceContext& context) const;

    // Media (path_media.cpp).
    /// The medium filling the solid of `material` (-1: none), or null.
    const Medium* mediumOf(int32_t material) const;
    /// Follows the path through `medium` up to `reach` (delta tracking): adds the medium's
    /// emission to `radiance`, and weighs `beta` by what the medium lets through to where the
    /// path scatters, or to `reach`.
    MediumStep trackMedium(const Ray& ray, double reach, const Medium& medium, Vec3& beta, Vec3& radiance,
                           TraceContext& context) const;
    /// The share of light that passes through `medium` along `ray` from t = `from` to `to`.
    Vec3 mediumTransmittance(const Ray& ray, double from, double to, const Medium& medium,
                             TraceContext& context) const;
    /// The boundaries of solids with a medium or an absorption that a shadow ray crossed,
    /// by where and whether it entered: the share of light they let through, each solid
    /// from where the ray enters it (or its start) to where it leaves (or its end).
    struct BoundaryCrossing {
        double t;
        int32_t material;
        bool entering;
    };
    Vec3 throughSolids(const Ray& ray, double tMax, std::vector<BoundaryCrossing>& crossings,
                       TraceContext& context) const;

    const RenderScene& scene_;
    const scene::SettingsDesc& settings_;
    const std::vector<Light>& lights_;
    const Background& background_;
    const Fog* fog_; ///< null: no fog
    const std::vector<Texture>& textures_;
    MaterialMixer mixer_;
    std::vector<Medium> media_; ///< by index of RenderScene::media
    /// By material: whether its surface is a clear boundary (path_integrator.cpp).
    std::vector<uint8_t> clearBoundary_;
    /// By material: whether it is clear glass light sampling solves paths through
    /// (path_caustics.cpp).
    std::vector<uint8_t> sharpGlass_;
    Emitters emitters_;
    EnvironmentLight environment_;
    bool hasAreaLights_;
    bool hides_; ///< whether some surface is hidden from some rays
    bool seesLights_; ///< whether some light is visible
    bool fillsSolids_; ///< whether a camera may stand in a filled solid (solid_around.hpp)
    bool solvesCaustics_; ///< whether light sampling solves for paths through glass
};

} // namespace crt::tracer
