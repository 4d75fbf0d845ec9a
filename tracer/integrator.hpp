// The Whitted-style shading of spec §6: ambient, diffuse, specular, shadows, reflection,
// refraction with Fresnel and Beer–Lambert absorption.
#pragma once

#include "tracer/background.hpp"
#include "tracer/fog.hpp"
#include "tracer/lights.hpp"
#include "tracer/material_mix.hpp"
#include "tracer/medium.hpp"
#include "tracer/render_scene.hpp"
#include "tracer/sampling.hpp"
#include "tracer/solid_around.hpp"
#include "tracer/texture.hpp"

#include <string>
#include <vector>

namespace crt::tracer {

/// The mutable state of one thread while it renders. Written for every ray, so it has its
/// cache lines to itself: one thread's context lives on a stack beside data the other
/// threads read as often, and sharing a line with it would make the cores take turns at it.
struct alignas(64) TraceContext {
    SampleRng rng{0, 0, 0};
    QueryScratch scratch;
    /// The shares of the surface points being shaded on the path, each point's after those
    /// of the points before it (MaterialMixer::resolve).
    std::vector<MaterialShare> shares;
    RayStats stats;
    bool inGlossy = false; ///< below a glossy bounce only one ray per bounce is spawned
    int reflections = 0;   ///< reflections on the path to the point being shaded
    int refractions = 0;   ///< refractions on the path to the point being shaded
    bool bent = false;     ///< a reflection or refraction is on the path (it is not the camera's line)
    double time = 0;       ///< the camera sample's time within the shutter: every ray of its path's
    SolidAroundCache solidAround; ///< the solid around the camera, as last found
};

/// What the scene uses, found once so per-ray code can skip what is absent (--stats says).
struct SceneFeatures {
    bool reflection = false;
    bool refraction = false;
    bool transparentShadows = false;
    bool textures = false;
    bool specular = false;
    bool blends = false;     ///< MaterialMap, Layered
    bool seeThrough = false; ///< a colour's alpha below 1 somewhere

    /// Those in use, by name ("reflection, textures"), or "plain" when none is.
    std::string names() const;
};

class Integrator {
public:
    /// Reads the scene, lights, background and textures while it lives.
    Integrator(const RenderScene& scene, const scene::SettingsDesc& settings, const std::vector<Light>& lights,
               const Background& background, const Fog* fog, const std::vector<Texture>& textures);

    /// The color seen along `ray` (unit direction) with `depth` reflections/refractions left
    /// (besides each kind's own limit, counted in `context`);
    /// `pathLength` is the distance travelled from the camera to the ray's origin (falloff),
    /// `medium` the material of the solid the ray travels in (-1: air), `departed` what
    /// the ray cannot meet again (RenderScene::departedPrimitive).
    Vec3 trace(const Ray& ray, int depth, double pathLength, int32_t medium, TraceContext& context,
               Departure departed = {}) const;
    /// A camera ray's color and alpha: as trace() in air, alpha 1; with a transparent
    /// background a ray that meets nothing is (0, 0, 0) with alpha 0 instead of the background.
    glm::dvec4 traceCamera(const Ray& ray, int depth, bool transparentBackground,
                           TraceContext& context) const;

    const SceneFeatures& features() const { return features_; }

private:
    struct ShadingPoint;
    /// The nearest hit along `ray` of a surface it sees, crossing those hidden from it (from
    /// the camera's line, or from reflections and refractions when context.bent): `ray`
    /// becomes the ray the hit is on, begun past the crossed surfaces `skipped` along it.
    bool nearestSeen(Ray& ray, Hit& hit, Departure departed, double& skipped, TraceContext& context) const;
    /// `color`, seen `distance` along the ray through what it passes on the way: the medium
    /// or absorption of the solid `medium` it is in, or else the fog.
    Vec3 passedOnTheWay(const Ray& ray, double distance, Vec3 color, double pathLength, int32_t medium,
                        TraceContext& context) const;
    /// The colour of what `ray` sees, hidden surfaces crossed and visible lights met (what
    /// trace() finds before fog and absorption), and how far along the ray it is (kInfinity:
    /// the background).
    /// Out of line: most scenes hide nothing and show no light, and trace() stays small.
    [[gnu::noinline]] Vec3 seenAlong(const Ray& ray, int depth, double pathLength, int32_t medium,
                                     TraceContext& context, Departure departed, double& distance) const;
    Vec3 shade(const Ray& ray, const Hit& hit, int depth, double pathLength, int32_t medium, TraceContext& context) const;
    /// The light plain material `material`, of colour `color` there, sends back from the point.
    Vec3 shadeMaterial(ShadingPoint& sp, int32_t material, const Vec3& color, int depth,
                       int32_t medium, TraceContext& context) const;
    /// The light that arrives at the point from straight behind it, through the surface.
    Vec3 passThrough(const ShadingPoint& sp, int depth, int32_t medium,
                     TraceContext& context) const;
    /// What of a shadow ray's light passes the crossing `hit` of a surface that is not plain.
    Vec3 seenThrough(const Ray& ray, const Hit& hit, TraceContext& context) const;
    /// The lights' share at the point, its material's diffuse weight being `diffuse`.
    Vec3 directLight(const ShadingPoint& sp, double diffuse, TraceContext& context) const;
    /// The fraction of light that reaches the point through the shadow ray (0: blocked).
    Vec3 transmittance(const Ray& ray, double tMax, Departure departed, TraceContext& context) const;
    /// What is seen along `ray` through `distance` of `medium` with `behind` at its end.
    Vec3 throughMedium(const Ray& ray, double distance, const Medium& medium, const Vec3& behind, double pathLength,
                       TraceContext& context) const;
    /// The light at `p` in `medium` that scatters back along −viewDir, per unit of its
    /// scattering coefficient.
    Vec3 lightInMedium(const Vec3& p, const Vec3& viewDir, const Medium& medium, double pathLength,
                       TraceContext& context) const;
    /// trace() of a reflected or refracted ray.
    Vec3 traceBent(const Ray& ray, int depth, double pathLength, int32_t medium, TraceContext& context,
                   Departure departed) const;
    Vec3 reflect(const ShadingPoint& sp, int depth, int32_t medium, TraceContext& context) const;
    /// The light along `refracted` into `nextMedium` (blurred around it on a glossy material).
    Vec3 refract(const ShadingPoint& sp, const Vec3& refracted, int depth, int32_t nextMedium,
                 TraceContext& context) const;

    const RenderScene& scene_;
    const scene::SettingsDesc& settings_;
    const std::vector<Light>& lights_;
    const Background& background_;
    const Fog* fog_; ///< null: no fog
    const std::vector<Texture>& textures_;
    MaterialMixer mixer_;
    std::vector<Medium> media_; ///< the scene's, by index
    SceneFeatures features_;
    Vec3 ambient_;
    int reflectionLimit_, refractionLimit_;
    bool hides_; ///< whether some surface is hidden from some rays
    bool seesLights_; ///< whether some light is visible
    bool fillsSolids_; ///< whether a camera may stand in a filled solid (solid_around.hpp)
};

} // namespace crt::tracer
