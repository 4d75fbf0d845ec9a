// Shading: c = E + A·C·kd + Σ lights [aₗ·Lₗ·C·kd + Sₗ·Fₗ·(C·kd·Lₗ·(n·l) + K·ks·Lₗ·(r·v)^sh)] + kr·K·R + kt·T.
#include "tracer/integrator.hpp"

#include "tracer/bump.hpp"
#include "tracer/surface_split.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// Glossy reflection and transmission: the mean of traceFrom over `samples` directions in a
/// cone around `axis` (half-angle up to 45° at glossiness 1; Hammersley points uniform in solid
/// angle, shifted per pixel sample), each folded back to the side `side` points to when it
/// strays across the surface. Below a glossy bounce only one ray is spawned per bounce, so the
/// cost does not grow exponentially.
template <typename TraceFrom>
Vec3 glossyMean(const Vec3& axis, const Vec3& side, double glossiness, int samples,
                TraceContext& context, TraceFrom&& traceFrom) {
    int count = context.inGlossy ? 1 : std::max(samples, 1);
    double cosMax = std::cos(std::clamp(glossiness, 0.0, 1.0) * kPi / 4);
    Vec3 helper = std::abs(axis.x) > 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    Vec3 t1 = glm::normalize(glm::cross(helper, axis)), t2 = glm::cross(axis, t1);
    Vec2 shift = context.rng.uniform2();
    bool wasGlossy = context.inGlossy;
    context.inGlossy = true;
    Vec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        Vec2 u = hammersley(static_cast<uint32_t>(i), static_cast<uint32_t>(count), shift);
        double cosTheta = 1 - u.x * (1 - cosMax);
        double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
        double phi = 2 * kPi * u.y;
        Vec3 dir = cosTheta * axis + sinTheta * (std::cos(phi) * t1 + std::sin(phi) * t2);
        double below = glm::dot(dir, side);
        if (below < 0) dir -= 2 * below * side;
        sum += traceFrom(glm::normalize(dir));
    }
    context.inGlossy = wasGlossy;
    return sum / static_cast<double>(count);
}

} // namespace

struct Integrator::ShadingPoint {
    /// The surface made in place where it is met (a copy just written is slow to read back).
    ShadingPoint(const RenderScene& scene, const Ray& ray, const Hit& h)
        : hit(h), si(scene.interaction(ray, h)) {}

    Hit hit;
    SurfaceInteraction si;
    bool entering; ///< the ray meets the outside of the surface
    const ShadingMaterial* material;
    Vec3 color;        ///< C: the material color or its texture
    Vec3 tint;         ///< K: C for metallic materials, else white
    Vec3 n;            ///< shading normal, facing the incoming ray
    Vec3 facingNormal; ///< geometric normal, facing the incoming ray
    Vec3 v;            ///< unit direction back along the incoming ray
    Vec3 d;            ///< the incoming direction
    double pathLength; ///< from the camera to this point
};

Integrator::Integrator(const RenderScene& scene, const scene::SettingsDesc& settings,
                       const std::vector<Light>& lights, const Background& background, const Fog* fog,
                       const std::vector<Texture>& textures)
    : scene_(scene), settings_(settings), lights_(lights), background_(background), fog_(fog), textures_(textures),
      mixer_(scene.materials, scene.blends, textures_),
      ambient_(rgb(settings.ambient)), reflectionLimit_(settings.reflectionLimit()),
      refractionLimit_(settings.refractionLimit()), hides_(scene.hidesAnything()),
      seesLights_(std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.visible(); })) {
    for (const scene::MediumDesc& medium : scene.media) media_.emplace_back(medium);
    fillsSolids_ = fillsSolids(scene, mixer_);
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const ShadingMaterial& m = scene.materials[i];
        bool plain = mixer_.isPlain(static_cast<int32_t>(i));
        features_.reflection |= m.reflectivity > 0 || (m.fresnel && m.transparency > 0);
        features_.refraction |= m.transparency > 0 || !plain;
        features_.transparentShadows |= m.transparency > 0 || !plain;
        features_.textures |= m.readsSurface();
        features_.specular |= m.specular > 0;
        features_.blends |= m.blend >= 0;
        features_.seeThrough |= !plain && m.blend < 0;
    }
}

std::string SceneFeatures::names() const {
    std::string list;
    auto add = [&](bool used, const char* name) {
        if (used) list += (list.empty() ? "" : ", ") + std::string(name);
    };
    add(reflection, "reflection");
    add(refraction, "refraction");
    add(transparentShadows, "transparent shadows");
    add(specular, "highlights");
    add(textures, "textures");
    add(blends, "material blends");
    add(seeThrough, "see-through colours");
    return list.empty() ? "plain" : list;
}

bool Integrator::nearestSeen(Ray& ray, Hit& hit, Departure departed, double& skipped, TraceContext& context) const {
    const uint8_t unseen = context.bent ? scene::kHiddenFromReflections : scene::kHiddenFromCamera;
    return scene_.intersectUnhidden(ray, unseen, hit, skipped, context.scratch, context.stats, departed);
}

Vec3 Integrator::trace(const Ray& ray, int depth, double pathLength, int32_t medium, TraceContext& context,
                       Departure departed) const {
    Hit hit;
    Vec3 color;
    double distance = kInfinity;
    if (hides_ || seesLights_) [[unlikely]] {
        color = seenAlong(ray, depth, pathLength, medium, context, departed, distance);
    } else if (scene_.intersect(ray, kInfinity, hit, context.scratch, context.stats, departed)) {
        distance = hit.t;
        color = shade(ray, hit, depth, pathLength, medium, context);
    } else {
        color = background_.radiance(ray.dir);
    }
    return passedOnTheWay(ray, distance, color, pathLength, medium, context);
}

Vec3 Integrator::passedOnTheWay(const Ray& ray, double distance, Vec3 color, double pathLength, int32_t medium,
                                TraceContext& context) const {
    if (medium >= 0 && scene_.materials[medium].medium >= 0) {
        color = throughMedium(ray, distance, media_[static_cast<size_t>(scene_.materials[medium].medium)], color,
                              pathLength, context);
    } else if (medium >= 0) {
        // Beer–Lambert absorption along the path inside the solid.
        Vec3 a = rgb(scene_.materials[medium].absorption);
        for (int i = 0; i < 3; ++i)
            if (a[i] > 0) color[i] *= std::exp(-a[i] * distance);
    } else if (fog_) {
        color = fog_->along(ray, distance).seen(color);
    }
    return color;
}

Vec3 Integrator::seenAlong(const Ray& ray, int depth, double pathLength, int32_t medium, TraceContext& context,
                           Departure departed, double& distance) const {
    Hit hit;
    Ray seen = ray;
    double skipped = 0;
    const bool found = nearestSeen(seen, hit, departed, skipped, context);
    distance = found ? skipped + hit.t : kInfinity;
    if (const Light* lamp = seesLights_ ? firstSeenLight(lights_, ray, distance) : nullptr) return lamp->color();
    if (found) return shade(seen, hit, depth, pathLength + skipped, medium, context);
    return background_.radiance(ray.dir);
}

glm::dvec4 Integrator::traceCamera(const Ray& ray, int depth, bool transparentBackground,
                                   TraceContext& context) const {
    // The solid the camera stands in, if it stands in a filled one.
    const int32_t medium = fillsSolids_ ? solidAround(scene_, mixer_, hides_, ray.origin, ray.time,
                                                      context.scratch, context.solidAround)
                                        : -1;
    if (!transparentBackground) return {trace(ray, depth, 0, medium, context), 1};
    double distance;
    const Vec3 color = seenAlong(ray, depth, 0, medium, context, {}, distance);
    if (distance == kInfinity) return glm::dvec4(0);
    return {passedOnTheWay(ray, distance, color, 0, medium, context), 1};
}

Vec3 Integrator::shade(const Ray& ray, const Hit& hit, int depth, double pathLength, int32_t medium,
                       TraceContext& context) const {
    ShadingPoint sp(scene_, ray, hit);
    sp.d = ray.dir;
    sp.v = -ray.dir;
    sp.pathLength = pathLength + hit.t;
    sp.entering = glm::dot(ray.dir, sp.si.normal) < 0;
    sp.facingNormal = sp.entering ? sp.si.normal : -sp.si.normal;
    const int32_t index = sp.si.material;
    const ShadingMaterial& m = scene_.materials[index];
    if (mixer_.isPlain(index)) {
        return shadeMaterial(sp, index, Vec3(mixer_.colorAt(m, sp.si)), depth, medium, context);
    }
    size_t first = context.shares.size();
    Vec3 passes = mixer_.resolve(index, sp.si, 1, context.shares);
    Vec3 c(0.0);
    for (size_t i = first; i < context.shares.size(); ++i) {
        MaterialShare share = context.shares[i]; // a copy: shading below adds to the list
        c += share.weight * shadeMaterial(sp, share.material, share.color, depth, medium, context);
    }
    context.shares.resize(first);
    if (passes != Vec3(0.0)) c += passes * passThrough(sp, depth, medium, context);
    return c;
}

Vec3 Integrator::shadeMaterial(ShadingPoint& sp, int32_t material, const Vec3& color, int depth,
                               int32_t medium, TraceContext& context) const {
    const ShadingMaterial& m = scene_.materials[material];
    sp.material = &m;
    sp.n = glm::dot(sp.si.shadingNormal, sp.v) < 0 ? -sp.si.shadingNormal : sp.si.shadingNormal;
    sp.color = color;
    sp.tint = m.metallic ? sp.color : Vec3(1.0);
    if (m.bump >= 0) sp.n = bumpedNormal(textures_[m.bump], sp.si, sp.n);

    const SurfaceSplit split = splitAt(m, sp.d, sp.n, sp.entering, sp.si.solid);
    double kr = split.kr, kt = split.kt;
    // The material's diffuse, less what reflection takes with conserveenergy.
    const double diffuse =
        m.conserveEnergy ? m.diffuse * std::max(0.0, 1 - split.reflectivity - m.transparency) : m.diffuse;
    Vec3 c = rgb(m.emission) + ambient_ * sp.color * diffuse;
    c += directLight(sp, diffuse, context);
    if (depth <= 0) return c;

    const Vec3& refracted = split.refracted;
    const bool refracts = split.refracts;
    // Each kind of bounce also has its own limit (reflectiondepth, refractiondepth).
    if (kr > 0 && context.reflections < reflectionLimit_) {
        ++context.reflections;
        c += kr * sp.tint * reflect(sp, depth, medium, context);
        --context.reflections;
    }
    if (kt > 0 && refracts && context.refractions < refractionLimit_) {
        ++context.refractions;
        int32_t nextMedium = sp.si.solid ? (sp.entering ? material : -1) : medium;
        c += kt * refract(sp, refracted, depth, nextMedium, context);
        --context.refractions;
    }
    return c;
}

Vec3 Integrator::directLight(const ShadingPoint& sp, double diffuse, TraceContext& context) const {
    const ShadingMaterial& m = *sp.material;
    Vec3 c(0.0);
    Vec3 diffuseColor = sp.color * diffuse;
    for (const Light& light : lights_) {
        c += light.ambient() * light.color() * diffuseColor;
        if (diffuse <= 0 && m.specular <= 0) continue;
        int samples = light.sampleCount();
        for (int s = 0; s < samples; ++s) {
            Vec2 jitter = samples > 1 ? context.rng.uniform2() : Vec2(0.5);
            LightSample ls = light.sample(sp.si.point, s, jitter);
            double nDotL = glm::dot(sp.n, ls.toLight);
            if (nDotL <= 0 || ls.color == Vec3(0.0)) continue;
            Vec3 origin = offsetRayOrigin(sp.si.point, sp.si.pointError, sp.si.normal, ls.toLight);
            Ray shadowRay = ls.atInfinity ? Ray{origin, ls.toLight, context.time} : Ray{origin, ls.target - origin, context.time};
            Vec3 visible = light.shadowless()
                               ? Vec3(1.0)
                               : transmittance(shadowRay, ls.atInfinity ? kInfinity : 1.0,
                                               scene_.departedPrimitive(sp.hit, sp.si, ls.toLight), context);
            if (visible == Vec3(0.0)) continue;
            double falloff = 1;
            if (light.falloff() > 0 && !ls.atInfinity) {
                double d = ls.distance + sp.pathLength;
                falloff = light.falloff() / (d * d);
            }
            // CS 488's attenuation, by the distance to the light alone (not the path).
            if (light.attenuates()) falloff *= light.attenuation(ls.distance);
            Vec3 term = diffuseColor * (m.brilliance == 1 ? nDotL : std::pow(nDotL, m.brilliance));
            if (m.specular > 0) {
                Vec3 r = 2 * nDotL * sp.n - ls.toLight;
                double rv = std::max(0.0, glm::dot(r, sp.v));
                term += sp.tint * m.specular * std::pow(rv, m.shininess);
            }
            c += visible * falloff * ls.color * term;
        }
    }
    return c;
}

Vec3 Integrator::transmittance(const Ray& ray, double tMax, Departure departed, TraceContext& context) const {
    ++context.stats.shadowRays;
    Vec3 through(1.0);
    const RenderScene& scene = scene_;
    scene_.forEachCrossing(ray, tMax, departed, context.scratch, context.stats,
                           [&](const Hit& hit) {
                               if (hides_ && (scene.hiddenFrom(hit) & scene::kHiddenFromShadows)) return true;
                               const int32_t index = scene.materialOf(hit);
                               const ShadingMaterial& m = scene.materials[index];
                               if (!mixer_.isPlain(index)) {
                                   through *= seenThrough(ray, hit, context);
                               } else if (m.transparency <= 0) {
                                   through = Vec3(0.0);
                               } else {
                                   through *= m.transparency * rgb(m.color);
                               }
                               return through != Vec3(0.0);
                           });
    return through;
}

Vec3 Integrator::seenThrough(const Ray& ray, const Hit& hit, TraceContext& context) const {
    SurfaceInteraction si = scene_.interaction(ray, hit);
    size_t first = context.shares.size();
    Vec3 through = mixer_.resolve(si.material, si, 1, context.shares);
    for (size_t i = first; i < context.shares.size(); ++i) {
        const MaterialShare& share = context.shares[i];
        through += share.weight * scene_.materials[share.material].transparency * share.color;
    }
    context.shares.resize(first);
    return through;
}

Vec3 Integrator::passThrough(const ShadingPoint& sp, int depth, int32_t medium,
                             TraceContext& context) const {
    // A refraction that does not bend: it takes a bounce and counts against the refraction
    // limit, so a stack of see-through surfaces ends where a stack of glass panes would.
    if (depth <= 0 || context.refractions >= refractionLimit_) return Vec3(0.0);
    ++context.refractions;
    ++context.stats.refractionRays;
    Ray next{offsetRayOrigin(sp.si.point, sp.si.pointError, sp.si.normal, sp.d), sp.d, context.time};
    Vec3 behind = trace(next, depth - 1, sp.pathLength, medium, context,
                        scene_.departedPrimitive(sp.hit, sp.si, sp.d));
    --context.refractions;
    return behind;
}

Vec3 Integrator::traceBent(const Ray& ray, int depth, double pathLength, int32_t medium, TraceContext& context,
                           Departure departed) const {
    const bool wasBent = context.bent;
    context.bent = true;
    const Vec3 color = trace(ray, depth, pathLength, medium, context, departed);
    context.bent = wasBent;
    return color;
}

Vec3 Integrator::reflect(const ShadingPoint& sp, int depth, int32_t medium, TraceContext& context) const {
    const ShadingMaterial& m = *sp.material;
    Vec3 mirror = glm::normalize(sp.d - 2 * glm::dot(sp.d, sp.n) * sp.n);
    auto traceFrom = [&](const Vec3& dir) {
        ++context.stats.reflectionRays;
        Ray next{offsetRayOrigin(sp.si.point, sp.si.pointError, sp.si.normal, dir), dir, context.time};
        return traceBent(next, depth - 1, sp.pathLength, medium, context, scene_.departedPrimitive(sp.hit, sp.si, dir));
    };
    if (m.glossiness <= 0) return traceFrom(mirror);
    return glossyMean(mirror, sp.facingNormal, m.glossiness, settings_.glossySamples, context,
                      traceFrom);
}

Vec3 Integrator::refract(const ShadingPoint& sp, const Vec3& refracted, int depth,
                         int32_t nextMedium, TraceContext& context) const {
    auto traceFrom = [&](const Vec3& dir) {
        ++context.stats.refractionRays;
        Ray next{offsetRayOrigin(sp.si.point, sp.si.pointError, sp.si.normal, dir), dir, context.time};
        return traceBent(next, depth - 1, sp.pathLength, nextMedium, context,
                         scene_.departedPrimitive(sp.hit, sp.si, dir));
    };
    const ShadingMaterial& m = *sp.material;
    if (m.glossiness <= 0) return traceFrom(refracted);
    // Frosted glass: the same cone around the refracted direction, kept below the surface.
    return glossyMean(refracted, -sp.facingNormal, m.glossiness, settings_.glossySamples,
                      context, traceFrom);
}

} // namespace crt::tracer
