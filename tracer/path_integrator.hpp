// Path tracing (Settings.integrator "path"): light that bounces off every surface, with
// next-event estimation and multiple importance sampling (docs/rendering.md, "Path tracing").
#pragma once

#include "tracer/background.hpp"
#include "tracer/fog.hpp"
#include "tracer/bsdf.hpp"
#include "tracer/emitters.hpp"
#include "tracer/environment_light.hpp"
#include "tracer/integrator.hpp"

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
    /// Where a path is: the surface it reached, or the point of a medium it scattered at,
    /// and what it knows of how it got there.
    struct Vertex;
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
    void alongSegment(Path& path, double reach, bool inMedium) const;
    /// A scattering in `medium` at t along the path's ray: light sampling through the phase
    /// function, and its draw of the next direction; false when the path ends.
    [[gnu::noinline]] bool scatterInMedium(Path& path, const Medium& medium, double t, TraceContext& context) const;
    /// The surface at `v` with `material` of `color`: its emission, light sampling through its
    /// BSDF, and the BSDF's draw of the next direction; false when the path ends.
    bool scatterAtSurface(Path& path, Vertex& v, int32_t material, const Vec3& color, FirstSurface* first,
                          TraceContext& context) const;
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
    /// The light of the area lights a path's ray meets before `tMax`, weighed against light
    /// sampling's chance of the same direction (`scatterPdf`, 0 when it has none).
    Vec3 areaLightsAlong(const Ray& ray, double tMax, double scatterPdf, double pathLength) const;
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
    /// Whether the emitter's surface is there at the sampled point, as seen from `from` (a CSG
    /// tree may have carved it away).
    bool emitterSurfaceAt(const EmitterSample& es, const Vec3& from, TraceContext& context) const;

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
    Emitters emitters_;
    EnvironmentLight environment_;
    bool hasAreaLights_;
    bool hides_; ///< whether some surface is hidden from some rays
    bool seesLights_; ///< whether some light is visible
    bool fillsSolids_; ///< whether a camera may stand in a filled solid (solid_around.hpp)
};

} // namespace crt::tracer
