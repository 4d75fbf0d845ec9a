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
    /// Where a path is: the surface it reached and what it knows of how it got there.
    struct Vertex;
    /// The plain material the path meets at the hit (one share of a blend, drawn by weight),
    /// or -1 when it passes the surface unbent; `beta` takes the draw's weight.
    int32_t drawMaterial(const SurfaceInteraction& si, Vec3& color, Vec3& beta, TraceContext& context) const;
    /// The light arriving from the lights and emitting surfaces, sent on by the BSDF towards
    /// the path's previous vertex.
    Vec3 directLight(const Vertex& v, const Bsdf& bsdf, TraceContext& context) const;
    Vec3 fromLights(const Vertex& v, const Bsdf& bsdf, TraceContext& context) const;
    /// The light of the area lights a path's ray meets before `tMax`, weighed against light
    /// sampling's chance of the same direction (`scatterPdf`, 0 when it has none).
    Vec3 areaLightsAlong(const Ray& ray, double tMax, double scatterPdf, double pathLength) const;
    Vec3 fromEmitter(const Vertex& v, const Bsdf& bsdf, TraceContext& context) const;
    Vec3 fromEnvironment(const Vertex& v, const Bsdf& bsdf, TraceContext& context) const;
    /// The share of light that passes along the segment (0, tMax) of `ray`: surfaces block it
    /// but for what a colour's alpha lets through unbent (glass is reached by the path's own
    /// refraction, so it is not counted twice).
    Vec3 visibility(const Ray& ray, double tMax, Departure departed, TraceContext& context) const;

    const RenderScene& scene_;
    const scene::SettingsDesc& settings_;
    const std::vector<Light>& lights_;
    const Background& background_;
    const Fog* fog_; ///< null: no fog
    const std::vector<Texture>& textures_;
    MaterialMixer mixer_;
    Emitters emitters_;
    EnvironmentLight environment_;
    bool hasAreaLights_;
    bool hides_; ///< whether some surface is hidden from some rays
    bool seesLights_; ///< whether some light is visible
};

} // namespace crt::tracer
