// Unidirectional path tracing: at every vertex, light sampling (each light, one emitting
// surface chosen by power) and BSDF sampling, weighted by the power heuristic; Russian
// roulette past the third bounce.
#include "tracer/path_integrator.hpp"

#include "tracer/bump.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// Bounces after which Russian roulette may end a path.
constexpr int kRouletteAfter = 3;

/// The first dimension of the pixel's sequence (SampleRng::sequence) that the choices at
/// the surfaces of bounce `bounce` (from 0) draw on: each bounce has room for 2^20 of them,
/// more than its crossings and lights can take, so no two bounces share a dimension, and
/// the camera's own (the point in the pixel and on the lens) come before.
uint32_t firstDimensionOf(int bounce) { return static_cast<uint32_t>(bounce + 1) << 20; }

/// A surface that sends all light on as it came, unbent and whole: transparency 1 at ior 1,
/// nothing reflected, diffused or given off. It bounds air, or a medium: paths and shadow
/// rays cross it as if it were not there, noting only which solid they are then in.
bool isClearBoundary(const ShadingMaterial& m) {
    return m.transparency == 1 && m.ior == 1 && m.reflectivity == 0 && m.reflectivityMin <= 0 && m.specular == 0 &&
           m.glossiness <= 0 && (m.conserveEnergy || m.diffuse == 0) && rgb(m.emission) == Vec3(0.0);
}

} // namespace

PathIntegrator::PathIntegrator(const RenderScene& scene, const scene::SettingsDesc& settings,
                               const std::vector<Light>& lights, const Background& background, const Fog* fog,
                               const std::vector<Texture>& textures)
    : scene_(scene), settings_(settings), lights_(lights), background_(background), fog_(fog), textures_(textures),
      mixer_(scene.materials, scene.blends, textures), media_(scene.media.begin(), scene.media.end()), emitters_(scene),
      environment_(background),
      hasAreaLights_(std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.hasArea(); })),
      hides_(scene.hidesAnything()),
      seesLights_(std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.visible(); })) {
    for (const ShadingMaterial& m : scene.materials) clearBoundary_.push_back(isClearBoundary(m));
    fillsSolids_ = fillsSolids(scene, mixer_);
    prepareCaustics();
}

int32_t PathIntegrator::drawMaterial(const SurfaceInteraction& si, Vec3& color, Vec3& beta,
                                     TraceContext& context) const {
    const int32_t index = si.material;
    if (mixer_.isPlain(index)) {
        color = Vec3(mixer_.colorAt(scene_.materials[static_cast<size_t>(index)], si));
        return index;
    }
    // One of the shares, or the light passing, drawn by weight: the draw's estimate of the
    // sum of them all is the drawn one over its chance.
    const size_t first = context.shares.size();
    const Vec3 passes = mixer_.resolve(index, si, 1, context.shares);
    const double passing = luminance(passes);
    double total = passing;
    for (size_t i = first; i < context.shares.size(); ++i) total += context.shares[i].weight;
    int32_t chosen = -1;
    if (total <= 0) {
        beta = Vec3(0.0);
    } else {
        double pick = context.rng.uniform() * total;
        for (size_t i = first; i < context.shares.size(); ++i) {
            const MaterialShare& share = context.shares[i];
            const bool last = i + 1 == context.shares.size() && passing <= 0;
            if (pick < share.weight || last) {
                chosen = share.material;
                color = share.color;
                beta *= total;
                break;
            }
            pick -= share.weight;
        }
        if (chosen < 0) beta *= passes * (total / passing);
    }
    context.shares.resize(first);
    return chosen;
}

Vec3 PathIntegrator::visibility(const Ray& ray, double tMax, Departure departed, TraceContext& context) const {
    ++context.stats.shadowRays;
    Vec3 through(1.0);
    std::vector<BoundaryCrossing> solids;
    scene_.forEachCrossing(ray, tMax, departed, context.scratch, context.stats, [&](const Hit& hit) {
        if (hides_ && (scene_.hiddenFrom(hit) & scene::kHiddenFromShadows)) return true;
        const int32_t index = scene_.materialOf(hit);
        if (mixer_.isPlain(index)) {
            const ShadingMaterial& m = scene_.materials[static_cast<size_t>(index)];
            if (!clearBoundary_[static_cast<size_t>(index)]) {
                through = Vec3(0.0);
            } else if (fillsSolid(m)) {
                const SurfaceInteraction si = scene_.interaction(ray, hit);
                if (si.solid) solids.push_back({hit.t, index, glm::dot(ray.dir, si.normal) < 0});
            }
        } else {
            const SurfaceInteraction si = scene_.interaction(ray, hit);
            size_t first = context.shares.size();
            through *= mixer_.resolve(index, si, 1, context.shares);
            context.shares.resize(first);
        }
        return through != Vec3(0.0);
    });
    if (!solids.empty() && through != Vec3(0.0)) through *= throughSolids(ray, tMax, solids, context);
    return through;
}

Vec3 PathIntegrator::originToward(const Vertex& v, const Vec3& dir) const {
    return v.inMedium ? v.si.point : offsetRayOrigin(v.si.point, v.si.pointError, v.si.normal, dir);
}

Departure PathIntegrator::departedToward(const Vertex& v, const Vec3& dir) const {
    return v.inMedium ? Departure{} : scene_.departedPrimitive(v.hit, v.si, dir);
}

template <typename Scatter>
Vec3 PathIntegrator::fromLights(const Vertex& v, const Scatter& bsdf, TraceContext& context) const {
    Vec3 sum(0.0);
    for (const Light& light : lights_) {
        const LightSample ls = light.sampleUniformly(v.si.point, context.rng.uniform2());
        if (ls.color == Vec3(0.0)) continue;
        const Vec3 f = bsdf.evalCos(ls.toLight);
        if (f == Vec3(0.0)) continue;
        const Vec3 origin = originToward(v, ls.toLight);
        const Ray shadow = ls.atInfinity ? Ray{origin, ls.toLight, context.time} : Ray{origin, ls.target - origin, context.time};
        const Vec3 visible = light.shadowless()
                                 ? Vec3(1.0)
                                 : visibility(shadow, ls.atInfinity ? kInfinity : 1.0,
                                              departedToward(v, ls.toLight), context);
        if (visible == Vec3(0.0)) {
            if constexpr (std::is_same_v<Scatter, Bsdf>) {
                if (solvesCaustics_ && light.fromPoint()) sum += causticFromLight(v, bsdf, light, context);
                if (solvesCaustics_ && solvedThroughGlass(light)) sum += causticFromAreaLight(v, bsdf, light, ls, context);
            }
            continue;
        }
        // An area light is also met by the paths the BSDF sends (areaLightsAlong).
        const double weight =
            light.hasArea() ? powerHeuristic(light.areaPdf(v.si.point, ls.toLight, ls.distance), bsdf.pdf(ls.toLight))
                            : 1.0;
        sum += visible * f * ls.color * (lightStrength(light, ls.distance, v.pathLength) * weight);
    }
    return sum;
}

template <typename Scatter>
Vec3 PathIntegrator::fromEmitter(const Vertex& v, const Scatter& bsdf, TraceContext& context) const {
    EmitterSample es;
    const double pick = context.rng.uniform();
    const Vec2 u = context.rng.uniform2();
    if (!emitters_.sample(v.si.point, pick, u, es)) return Vec3(0.0);
    const Vec3 toEmitter = glm::normalize(es.point - v.si.point);
    const Vec3 f = bsdf.evalCos(toEmitter);
    if (f != Vec3(0.0) && (!es.mayBeCarved || emitterSurfaceAt(es, v.si.point, context))) {
        const Vec3 origin = originToward(v, toEmitter);
        const Vec3 visible = visibility(Ray{origin, es.point - origin, context.time}, kShortOfEmitter,
                                        departedToward(v, toEmitter), context);
        if (visible != Vec3(0.0))
            return visible * f * es.radiance * (powerHeuristic(es.pdf, bsdf.pdf(toEmitter)) / es.pdf);
    }
    // Clear glass on the straight line hides the point; the light may come through it.
    if constexpr (std::is_same_v<Scatter, Bsdf>) {
        if (solvesCaustics_) return causticFromEmitter(v, bsdf, es, context);
    }
    return Vec3(0.0);
}

bool PathIntegrator::emitterSurfaceAt(const EmitterSample& es, const Vec3& from, TraceContext& context) const {
    // A short ray across the point along the light's way. A CSG tree's crossings are those of
    // the whole line, so the ray meets the operand there exactly where the tree kept its
    // surface. Its reach stays well above the rounding of the point and of the crossing.
    const Vec3 offset = es.point - from;
    const double distance = glm::length(offset);
    const Vec3 dir = offset / distance;
    const Vec3 magnitude = glm::abs(es.point);
    const double reach = 1e-6 * distance + 1e-9 * std::max({magnitude.x, magnitude.y, magnitude.z});
    Hit hit;
    return scene_.intersect(Ray{es.point - reach * dir, dir, context.time}, 2 * reach, hit, context.scratch,
                            context.stats) &&
           hit.primitive == es.primitive && hit.instance == es.instance;
}

template <typename Scatter>
Vec3 PathIntegrator::fromEnvironment(const Vertex& v, const Scatter& bsdf, TraceContext& context) const {
    if (!environment_.active()) return Vec3(0.0);
    double pdf = 0;
    const Vec3 dir = environment_.sample(context.rng.uniform2(), pdf);
    if (!(pdf > 0)) return Vec3(0.0);
    const Vec3 f = bsdf.evalCos(dir);
    if (f == Vec3(0.0)) return Vec3(0.0);
    const Vec3 visible = visibility(Ray{originToward(v, dir), dir, context.time}, kInfinity, departedToward(v, dir), context);
    if (visible == Vec3(0.0)) return Vec3(0.0);
    return visible * f * background_.radiance(dir) * (powerHeuristic(pdf, bsdf.pdf(dir)) / pdf);
}

template <typename Scatter>
Vec3 PathIntegrator::directLight(const Vertex& v, const Scatter& bsdf, TraceContext& context) const {
    return fromLights(v, bsdf, context) + fromEmitter(v, bsdf, context) + fromEnvironment(v, bsdf, context);
}

/// A path being traced: its ray, the light it has gathered and the share it carries, and
/// what it knows of how it got there.
struct PathIntegrator::Path {
    Ray ray;
    Vec3 radiance{0.0}, beta{1.0};
    Departure departed;
    int32_t medium = -1; ///< the material of the solid it is in (-1: air)
    /// The last scattering vertex: where a BSDF- or phase-sampled ray started, and its density
    /// (0 for a mirror, glass or the camera: no light sampling competes with those).
    Vec3 scatteredFrom{0.0};
    double scatterPdf = 0;
    double pathLength = 0; ///< from the camera to the ray's origin
    /// pathLength at the last vertex where a lobe light sampling reaches scattered the path
    /// (-1: none yet; mirrors and glass do not count).
    double pathLengthAtScatter = -1;
    int bounce = 0;
    CausticStart caustic; ///< the way through clear glass the path is on, if any

    /// Goes on past the surface at `v` as if it were not there.
    void crossStraight(const RenderScene& scene, const Vertex& v) {
        ray = Ray{offsetRayOrigin(v.si.point, v.si.pointError, v.si.normal, ray.dir), ray.dir, ray.time};
        departed = scene.departedPrimitive(v.hit, v.si, ray.dir);
    }
};

Vec3 PathIntegrator::areaLightsAlong(const Path& path, double tMax, TraceContext& context) const {
    const Ray& ray = path.ray;
    // The path's length from the point the light is reckoned to light: its last scattering
    // vertex, through mirrors and glass (the ray's origin for the camera's own path).
    const double before = path.pathLengthAtScatter >= 0 ? path.pathLength - path.pathLengthAtScatter : 0;
    Vec3 sum(0.0);
    for (const Light& light : lights_) {
        // A shadowless light is met through whatever stands before it, as light sampling sees it.
        const double t = light.crossing(ray, light.shadowless() ? kInfinity : tMax);
        if (t == kInfinity) continue;
        // The radiance that gives light sampling's estimate: the light spread over the
        // parallelogram, each point lighting as a point light does (so it grows with the
        // distance, as a point light without falloff keeps its strength there). Through a
        // mirror or a pane, the light keeps its strength as a point light does through them
        // (Caustics).
        const double distance = before + t;
        const double pdf = light.areaPdf(ray.origin, ray.dir, distance);
        if (pdf == kInfinity) continue;
        double weight = 1;
        if (path.scatterPdf > 0)
            weight = powerHeuristic(path.scatterPdf, pdf);
        else if (path.caustic.crossings > 0 && solvedThroughGlass(light))
            weight = causticWeight(path.caustic, light, ray.at(t), context);
        sum += light.color() * (lightStrength(light, distance, path.pathLength - before) * pdf * weight);
    }
    return sum;
}

[[gnu::always_inline]] inline bool PathIntegrator::nextBounce(Path& path, TraceContext& context) const {
    ++path.bounce;
    context.rng.skipTo(firstDimensionOf(path.bounce));
    if (path.bounce <= kRouletteAfter) return true;
    // Russian roulette: a path carrying little light ends with the chance it lacks, and one
    // that goes on carries that much more.
    const double keep = std::min(1.0, std::max({path.beta.r, path.beta.g, path.beta.b}));
    if (context.rng.uniform() >= keep) return false;
    path.beta /= keep;
    return true;
}

[[gnu::always_inline]] inline void PathIntegrator::alongSegment(Path& path, double reach, bool inMedium,
                                                                TraceContext& context) const {
    if (path.bounce > 0 && hasAreaLights_) path.radiance += path.beta * areaLightsAlong(path, reach, context);
    if (path.medium >= 0 && !inMedium) {
        // Beer–Lambert absorption along the path inside the solid.
        const Vec3 a = rgb(scene_.materials[static_cast<size_t>(path.medium)].absorption);
        for (int i = 0; i < 3; ++i)
            if (a[i] > 0) path.beta[i] *= reach < kInfinity ? std::exp(-a[i] * reach) : 0.0;
    } else if (path.medium < 0 && fog_) {
        const FogCrossing fog = fog_->along(path.ray, reach);
        path.radiance += path.beta * fog.inscattered;
        path.beta *= fog.transmittance;
    }
}

bool PathIntegrator::scatterInMedium(Path& path, const Medium& medium, double t, TraceContext& context) const {
    if (path.bounce >= settings_.bounces) return false;
    Vertex v;
    v.inMedium = true;
    v.si.point = path.ray.at(t);
    v.pathLength = path.pathLength += t * glm::length(path.ray.dir);
    const PhaseScatter phase{medium, glm::normalize(path.ray.dir)};
    path.radiance += path.beta * directLight(v, phase, context);
    const Vec3 wi = medium.samplePhase(phase.d, context.rng.uniform2());
    path.scatteredFrom = v.si.point;
    path.scatterPdf = phase.pdf(wi);
    path.pathLengthAtScatter = v.pathLength;
    path.ray = Ray{v.si.point, wi, path.ray.time};
    path.departed = {};
    return nextBounce(path, context);
}

Bsdf PathIntegrator::bsdfAt(Vertex& v, const ShadingMaterial& m, const Vec3& color, const Vec3& d) const {
    const bool entering = glm::dot(d, v.si.normal) < 0;
    v.n = glm::dot(v.si.shadingNormal, d) > 0 ? -v.si.shadingNormal : v.si.shadingNormal;
    if (m.bump >= 0) v.n = bumpedNormal(textures_[static_cast<size_t>(m.bump)], v.si, v.n);
    return Bsdf(m, color, d, v.n, entering ? v.si.normal : -v.si.normal, entering, v.si.solid);
}

[[gnu::always_inline]] inline bool PathIntegrator::scatterAtSurface(Path& path, Vertex& v, int32_t material, const Vec3& color,
                                      FirstSurface* first, TraceContext& context) const {
    const ShadingMaterial& m = scene_.materials[static_cast<size_t>(material)];
    const Vec3 emission = rgb(m.emission);
    if (emission != Vec3(0.0)) {
        double weight = 1;
        if (path.scatterPdf > 0)
            weight = powerHeuristic(path.scatterPdf, emitters_.pdf(v.hit, path.scatteredFrom, v.si.point, v.si.normal));
        else if (path.caustic.crossings > 0)
            weight = causticWeight(path.caustic, v, context);
        path.radiance += path.beta * emission * weight;
    }
    const bool wantsFirst = first && !first->found;
    if (path.bounce >= settings_.bounces && !wantsFirst) return false;

    const Vec3& d = path.ray.dir;
    const bool entering = glm::dot(d, v.si.normal) < 0;
    const Bsdf bsdf = bsdfAt(v, m, color, d);
    if (wantsFirst && bsdf.reachable()) *first = {bsdf.albedo(), v.n, true};
    if (path.bounce >= settings_.bounces) return false;
    v.bounce = path.bounce;
    v.inAir = path.medium < 0;
    if (bsdf.reachable()) path.radiance += path.beta * directLight(v, bsdf, context);

    BsdfSample next;
    const double pick = context.rng.uniform();
    const Vec2 u = context.rng.uniform2();
    if (!bsdf.sample(pick, u, next)) return false;
    path.beta *= next.weight;
    if (path.beta == Vec3(0.0)) return false;
    path.scatteredFrom = v.si.point;
    path.scatterPdf = next.pdf;
    if (next.pdf > 0) path.pathLengthAtScatter = v.pathLength;
    if (solvesCaustics_) noteCausticBounce(path.caustic, v, next);
    if (next.transmitted) {
        ++context.stats.refractionRays;
        if (v.si.solid) path.medium = entering ? material : -1;
    } else {
        ++context.stats.reflectionRays;
    }
    path.ray = Ray{offsetRayOrigin(v.si.point, v.si.pointError, v.si.normal, next.wi), next.wi, path.ray.time};
    path.departed = scene_.departedPrimitive(v.hit, v.si, next.wi);
    return nextBounce(path, context);
}

glm::dvec4 PathIntegrator::traceCamera(const Ray& cameraRay, bool transparentBackground, TraceContext& context,
                                       FirstSurface* first) const {
    Path path;
    path.ray = cameraRay;
    if (fillsSolids_)
        path.medium = solidAround(scene_, mixer_, hides_, cameraRay.origin, cameraRay.time, context.scratch,
                                  context.solidAround);
    context.rng.skipTo(firstDimensionOf(path.bounce));
    // Crossing surfaces as if they were not there (hidden, see-through, clear boundaries) takes
    // no bounce; this bounds how many a path may cross.
    const int mostCrossings = 4 * settings_.bounces + 16;
    for (int crossings = 0;; ++crossings) {
        Vertex v;
        const Ray& ray = path.ray;
        const bool found = scene_.intersect(ray, kInfinity, v.hit, context.scratch, context.stats, path.departed);
        double reach = found ? v.hit.t : kInfinity;
        const Medium* fill = mediumOf(path.medium);
        MediumStep step;
        if (fill) {
            step = trackMedium(ray, reach, *fill, path.beta, path.radiance, context);
            if (step.scattered) reach = step.t;
        }
        // The camera, mirrors and glass see the visible lights as the Whitted integrator does
        // (light sampling cannot reach them through a mirror); other bounces meet every area
        // light and weigh it against light sampling.
        const Light* lamp = path.scatterPdf == 0 && seesLights_ ? firstSeenLight(lights_, ray, reach) : nullptr;
        alongSegment(path, reach, fill != nullptr, context);
        if (lamp) {
            path.radiance += path.beta * lamp->color();
            break;
        }
        if (step.scattered) {
            path.caustic.crossings = -1;
            if (!scatterInMedium(path, *fill, step.t, context)) break;
            continue;
        }
        if (!found) {
            if (crossings == 0 && transparentBackground) return glm::dvec4(0.0);
            const double weight =
                path.scatterPdf > 0 ? powerHeuristic(path.scatterPdf, environment_.pdf(ray.dir)) : 1.0;
            path.radiance += path.beta * background_.radiance(ray.dir) * weight;
            break;
        }
        v.si = scene_.interaction(ray, v.hit);
        v.pathLength = path.pathLength += v.hit.t;
        const uint8_t unseen = path.bounce == 0 ? scene::kHiddenFromCamera : scene::kHiddenFromReflections;
        if (hides_ && (scene_.hiddenFrom(v.hit) & unseen)) {
            // Crossed as if it were not there, as a see-through surface is below.
            if (crossings > mostCrossings) break;
            path.crossStraight(scene_, v);
            continue;
        }
        Vec3 color;
        const int32_t material = drawMaterial(v.si, color, path.beta, context);
        if (material < 0 || clearBoundary_[static_cast<size_t>(material)]) {
            // Through the surface unbent, as if it were not there (into or out of a clear
            // boundary's solid): the last scattering vertex stays the one light sampling was
            // weighed against, as shadow rays cross it too.
            if (path.beta == Vec3(0.0) || crossings > mostCrossings) break;
            if (material >= 0 && v.si.solid) path.medium = glm::dot(ray.dir, v.si.normal) < 0 ? material : -1;
            path.crossStraight(scene_, v);
            path.caustic.crossings = -1;
            continue;
        }
        if (!scatterAtSurface(path, v, material, color, first, context)) break;
    }
    return {path.radiance, 1};
}

} // namespace crt::tracer
