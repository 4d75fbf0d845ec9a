// Caustics under the path integrator: light reaching a surface through clear glass, found by
// manifold next-event estimation (docs/rendering.md, "Caustics").
//
// Light sampling aims a shadow ray straight at a light, or a point of an area light or an
// emitter. Where clear glass stands between, the light arrives bent, along a way no straight
// ray follows: the paths' own bounces find it only by chance (the bright, noisy spot under a
// glass ball), and a point light's never. So when the straight line crosses only clear
// glass, light sampling also solves for the path through it. From the straight line,
// Newton's method turns the direction leaving the surface point until the path it starts,
// refracted at each glass surface the line crosses, lands on the light's point (Hanika et al.
// 2015, "Manifold next event estimation", in its shooting form: the unknown is the
// direction, the residual where the path meets a plane through the target); near curved
// glass, and for a point light where that fails, from more seeds too (glassChainsTo), every
// path found counting. The light a path brings is weighed by how the glass spreads it: the
// target plane's area per solid angle of directions at the surface point, measured by
// turning the direction a little.
//
// The solves are a function of the two points alone. So a path the bounces found (a lobe
// light sampling reaches, then only clear glass, then an emitter or an area light) asks them
// whether light sampling reaches the same path: if so, the two are weighed against each other
// by the power heuristic; if the solves reach other paths or none, the bounce's path counts
// whole. Together they count every path to an emitter or area light once, however many paths
// join the two points.
#include "tracer/path_integrator.hpp"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// The most glass surfaces a solved path crosses.
constexpr int kMostCrossings = 8;
/// Newton steps before a solve gives up; it converges in a few where the glass is smooth.
constexpr int kMostNewtonSteps = 20;
/// How far (in the tangents of the chart, about radians) a Newton step may turn the
/// direction: at first, at most, and least before the solve gives up. A step that lands no
/// nearer shrinks the reach fourfold; one that does doubles it.
constexpr double kFirstReach = 0.25, kMostReach = 1, kLeastReach = 1e-3;
/// Where no path joins the points, the solve gives up early: when Newton's step would turn
/// the direction further than this (the landing barely follows the direction there), or
/// when two steps in a row each bring the landing less than a tenth nearer.
constexpr double kFarthestTurn = 4;
constexpr double kSlowStep = 0.9;
/// The turn (in the tangents of the chart) by which the slope of the landing is measured:
/// far above the rounding of the landing, far below the glass's curvature.
constexpr double kTurn = 1e-6;
/// How near the target a solved path lands, as a share of the distance between the points.
constexpr double kLandingTolerance = 1e-7;
/// Two solved directions closer than this (1 − cos) are the same path.
constexpr double kSameDirection = 1e-9;

/// Glass nearer than this many of its radii (the largest half-extent of its bounds) seeds
/// solves fanned across it: this many on each side of its middle.
constexpr double kNearGlass = 1.2;
constexpr int kFanSeeds = 2;

/// The density, by area of the emitter, of a point light sampling chose with `solidAnglePdf`
/// seen from `from`.
double areaDensity(double solidAnglePdf, const Vec3& from, const Vec3& point, const Vec3& normal) {
    const Vec3 offset = from - point;
    const double distance2 = glm::dot(offset, offset);
    return distance2 > 0 ? solidAnglePdf * std::abs(glm::dot(normal, offset)) / (distance2 * std::sqrt(distance2))
                         : 0;
}

} // namespace

/// The directions around the straight line to the target, by the tangents of their angles
/// from it along its Frame's u and v (a gnomonic chart: it covers the hemisphere around the
/// line, and Newton's steps stay straight in it).
struct PathIntegrator::DirectionChart {
    Frame frame;
    Vec3 at(const Vec2& p) const { return glm::normalize(frame.w + p.x * frame.u + p.y * frame.v); }
    /// The solid angle per unit area of the chart at p.
    static double solidAngleDensity(const Vec2& p) { return std::pow(1 + glm::dot(p, p), -1.5); }
};

struct PathIntegrator::ChainRay {
    Ray ray;
    Departure departed;
    Vec3 throughput{1.0};
    double chance = 1;
    double length = 0;   ///< of the path up to the ray's origin
    int32_t medium = -1; ///< the solid the ray is in (-1: air)

    /// Goes `t` along the ray: its length, and Beer–Lambert absorption in the solid it is in,
    /// as a path has it.
    void advance(const RenderScene& scene, double t) {
        length += t;
        if (medium < 0) return;
        const Vec3 a = rgb(scene.materials[static_cast<size_t>(medium)].absorption);
        for (int i = 0; i < 3; ++i)
            if (a[i] > 0) throughput[i] *= std::exp(-a[i] * t);
    }
};

void PathIntegrator::prepareCaustics() {
    for (size_t i = 0; i < scene_.materials.size(); ++i) {
        const ShadingMaterial& m = scene_.materials[i];
        sharpGlass_.push_back(m.transparency > 0 && m.glossiness <= 0 && m.medium < 0 &&
                              rgb(m.emission) == Vec3(0.0) && !clearBoundary_[i]);
    }
    const bool lightsToSolveFor = std::any_of(lights_.begin(), lights_.end(),
                                              [](const Light& l) { return l.fromPoint() || solvedThroughGlass(l); });
    solvesCaustics_ = (!emitters_.empty() || lightsToSolveFor) && !fog_ && !hides_ &&
                      std::any_of(sharpGlass_.begin(), sharpGlass_.end(), [](uint8_t g) { return g != 0; });
}

void PathIntegrator::noteCausticBounce(CausticStart& start, const Vertex& v, const BsdfSample& next) const {
    if (next.pdf > 0) {
        // A lobe light sampling reaches: a way through glass may start here.
        if (v.inAir)
            start = {v, next.wi, next.pdf, 0};
        else
            start.crossings = -1;
    } else if (start.crossings >= 0 && next.sharpRefraction && isSharpGlass(v.si.material)) {
        ++start.crossings;
        start.chance *= next.lobeChance;
    } else {
        start.crossings = -1;
    }
}

bool PathIntegrator::followGlass(const Vertex& from, const Vec3& dir, int crossings, ChainRay& out,
                                 TraceContext& context) const {
    out = ChainRay{Ray{originToward(from, dir), dir, context.time}, departedToward(from, dir)};
    for (int i = 0; i < crossings; ++i) {
        Vertex v;
        if (!scene_.intersect(out.ray, kInfinity, v.hit, context.scratch, context.stats, out.departed)) return false;
        v.si = scene_.interaction(out.ray, v.hit);
        if (!isSharpGlass(v.si.material)) return false;
        out.advance(scene_, v.hit.t);
        const ShadingMaterial& m = scene_.materials[static_cast<size_t>(v.si.material)];
        SharpRefraction refraction;
        if (!bsdfAt(v, m, Vec3(mixer_.colorAt(m, v.si)), out.ray.dir).sharpRefraction(refraction)) return false;
        out.throughput *= refraction.weight;
        out.chance *= refraction.chance;
        if (v.si.solid) out.medium = glm::dot(out.ray.dir, v.si.normal) < 0 ? v.si.material : -1;
        out.ray = Ray{offsetRayOrigin(v.si.point, v.si.pointError, v.si.normal, refraction.wi), refraction.wi,
                      context.time};
        out.departed = scene_.departedPrimitive(v.hit, v.si, refraction.wi);
    }
    return true;
}

bool PathIntegrator::landing(const Vertex& from, const Vec3& dir, const ChainTarget& target, int crossings,
                             Vec2& miss, ChainRay& ray, TraceContext& context) const {
    if (!followGlass(from, dir, crossings, ray, context)) return false;
    const Vec3& normal = target.frame.w;
    const double t = glm::dot(target.point - ray.ray.origin, normal) / glm::dot(ray.ray.dir, normal);
    if (!(t > 0 && t < kInfinity)) return false;
    const Vec3 offset = ray.ray.at(t) - target.point;
    miss = {glm::dot(offset, target.frame.u), glm::dot(offset, target.frame.v)};
    return true;
}

bool PathIntegrator::landingSlope(const Vertex& from, const DirectionChart& chart, const Vec2& p,
                                  const ChainTarget& target, int crossings, const Vec2& miss, glm::dmat2& slope,
                                  TraceContext& context) const {
    ChainRay ray;
    Vec2 alongU, alongV;
    if (!landing(from, chart.at(p + Vec2(kTurn, 0)), target, crossings, alongU, ray, context) ||
        !landing(from, chart.at(p + Vec2(0, kTurn)), target, crossings, alongV, ray, context))
        return false;
    slope = glm::dmat2((alongU - miss) / kTurn, (alongV - miss) / kTurn);
    return true;
}

bool PathIntegrator::glassExtent(const Hit& hit, Vec3& middle, double& radius) const {
    if (hit.instance >= 0) return false;
    const Primitive& glass = scene_.primitives[static_cast<size_t>(hit.primitive)];
    const Bounds3 local = geometryBounds(glass.geometry);
    if (glass.transform >= RenderScene::kFirstMovingTransform || !local.finite()) return false;
    middle = (local.lo + local.hi) * 0.5;
    const Vec3 half = (local.hi - local.lo) * 0.5;
    radius = std::max({half.x, half.y, half.z});
    if (glass.transform >= 0) {
        const Transform& toWorld = scene_.transforms[static_cast<size_t>(glass.transform)].toWorld;
        middle = toWorld.point(middle);
        radius = 0.5 * glm::length(toWorld.point(local.hi) - toWorld.point(local.lo));
    }
    return true;
}

int PathIntegrator::glassChainsTo(const Vertex& from, const ChainTarget& target, Chains& found,
                                  TraceContext& context) const {
    // The straight line says how many glass surfaces the path crosses, and is the first seed.
    const Vec3 dir = glm::normalize(target.point - from.si.point);
    if (glm::dot(dir, from.n) <= 0) return 0;
    const Vec3 origin = originToward(from, dir);
    int crossings = 0;
    bool glassOnly = true;
    Hit nearest;
    nearest.t = kInfinity;
    scene_.forEachCrossing(Ray{origin, target.point - origin, context.time}, kShortOfEmitter,
                           departedToward(from, dir), context.scratch, context.stats, [&](const Hit& hit) {
                               glassOnly = isSharpGlass(scene_.materialOf(hit)) && ++crossings <= kMostCrossings;
                               if (hit.t < nearest.t) nearest = hit;
                               return glassOnly;
                           });
    if (!glassOnly || crossings == 0 || from.bounce + crossings >= settings_.bounces) return 0;

    int count = 0;
    const auto solve = [&](const Vec3& seed) {
        Chain chain;
        if (count == static_cast<int>(found.size()) || !solveFrom(from, target, seed, crossings, chain, context))
            return;
        for (int i = 0; i < count; ++i)
            if (glm::dot(found[static_cast<size_t>(i)].wi, chain.wi) >= 1 - kSameDirection) return;
        found[static_cast<size_t>(count++)] = chain;
    };
    solve(dir);
    Vec3 middle;
    double radius;
    if (!glassExtent(nearest, middle, radius)) return count;
    const Vec3 toMiddle = glm::normalize(middle - from.si.point);
    const double away = glm::length(middle - from.si.point);
    // Close by, curved glass fills much of the view and joins the points by several paths (a
    // ball seen from the floor it stands on): seeds fanned across it, in the plane through
    // the point, its middle and the target. Flat faces (a box, a pane) bend every direction
    // alike, and the straight line's seed finds their path.
    const Geometry& shape = scene_.primitives[static_cast<size_t>(nearest.primitive)].geometry;
    const bool curved = !holds<BoxGeometry>(shape) && !isFlat(shape);
    const bool near = curved && away < kNearGlass * radius;
    if (Vec3 side = target.point - from.si.point - glm::dot(target.point - from.si.point, toMiddle) * toMiddle;
        near && glm::dot(side, side) > 0) {
        side = glm::normalize(side);
        const double cone = std::asin(std::min(1.0, radius / away));
        for (int k = -kFanSeeds; k <= kFanSeeds; ++k) {
            const double angle = k * cone / (kFanSeeds + 0.5);
            solve(std::cos(angle) * toMiddle + std::sin(angle) * side);
        }
    }
    // A light's position has no other way to reach the point: where the glass bends the
    // path far from the straight line (the rim of a ball's caustic), two more seeds: toward
    // the glass's middle, and the straight line mirrored about it. An emitter's paths are
    // also found by the bounces, which cover what the solves miss.
    if (target.bouncesReach || count > 0) return count;
    if (!near) solve(toMiddle);
    if (count == 0) solve(glm::normalize(2 * glm::dot(dir, toMiddle) * toMiddle - dir));
    return count;
}

bool PathIntegrator::solveFrom(const Vertex& from, const ChainTarget& target, const Vec3& seed, int crossings,
                               Chain& out, TraceContext& context) const {
    // Newton's method on the landing, its slope measured at the start and after a step
    // that fails, corrected by Broyden's update after one that does not.
    if (glm::dot(seed, from.n) <= 0) return false;
    const double distance = glm::length(target.point - from.si.point);
    const DirectionChart chart{Frame::fromAxis(seed)};
    Vec2 p(0.0), miss;
    ChainRay ray;
    glm::dmat2 slope;
    if (!landing(from, seed, target, crossings, miss, ray, context) ||
        !landingSlope(from, chart, p, target, crossings, miss, slope, context))
        return false;
    double reach = kFirstReach;
    bool measured = true;
    int slowSteps = 0;
    for (int step = 0; glm::length(miss) > kLandingTolerance * distance; ++step) {
        if (step == kMostNewtonSteps || !(std::abs(glm::determinant(slope)) > 0)) return false;
        Vec2 turn = -(glm::inverse(slope) * miss);
        const double size = glm::length(turn);
        if (!(size > 0) || size > kFarthestTurn) return false;
        if (size > reach) turn *= reach / size;
        ChainRay next;
        Vec2 nextMiss;
        if (landing(from, chart.at(p + turn), target, crossings, nextMiss, next, context) &&
            glm::length(nextMiss) < glm::length(miss)) {
            slowSteps = glm::length(nextMiss) > kSlowStep * glm::length(miss) ? slowSteps + 1 : 0;
            if (slowSteps == 2) return false;
            slope += glm::outerProduct(nextMiss - miss - slope * turn, turn) / glm::dot(turn, turn);
            p += turn, miss = nextMiss, ray = next;
            reach = std::min(kMostReach, 2 * reach);
            measured = false;
        } else if (!measured) {
            if (!landingSlope(from, chart, p, target, crossings, miss, slope, context)) return false;
            measured = true;
        } else {
            reach = std::min(reach, glm::length(turn)) / 4;
            if (reach < kLeastReach) return false;
        }
    }
    const Vec3 dir = chart.at(p);
    if (!landingSlope(from, chart, p, target, crossings, miss, slope, context)) return false;
    // The last stretch must reach the target unblocked: the emitter there, or the light.
    double lastStretch = glm::dot(target.point - ray.ray.origin, ray.ray.dir);
    if (target.primitive >= 0) {
        Hit hit;
        if (!scene_.intersect(ray.ray, kInfinity, hit, context.scratch, context.stats, ray.departed) ||
            hit.primitive != target.primitive || hit.instance != target.instance ||
            glm::length(ray.ray.at(hit.t) - target.point) > 4 * kLandingTolerance * distance)
            return false;
        lastStretch = hit.t;
    } else {
        const Vec3 visible = visibility(Ray{ray.ray.origin, target.point - ray.ray.origin, context.time}, 1.0,
                                        ray.departed, context);
        if (visible == Vec3(0.0)) return false;
        ray.throughput *= visible;
    }
    ray.advance(scene_, lastStretch);
    const double spread = std::abs(glm::determinant(slope)) / DirectionChart::solidAngleDensity(p);
    out = {dir, ray.ray.dir, ray.throughput, ray.chance, spread, ray.length, crossings};
    return true;
}

Vec3 PathIntegrator::causticFromEmitter(const Vertex& v, const Bsdf& bsdf, const EmitterSample& es,
                                        TraceContext& context) const {
    if (!v.inAir) return Vec3(0.0);
    Chains chains;
    const int count =
        glassChainsTo(v, {es.point, Frame::fromAxis(es.normal), es.primitive, es.instance}, chains, context);
    // Light sampling's density of a direction: the point's density by area, times the
    // chain's area per solid angle.
    const double pointPdf = areaDensity(es.pdf, v.si.point, es.point, es.normal);
    Vec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        const Chain& chain = chains[static_cast<size_t>(i)];
        const Vec3 f = bsdf.evalCos(chain.wi);
        const double pdf = pointPdf * chain.spread;
        if (f == Vec3(0.0) || !(pdf > 0)) continue;
        const double weight = powerHeuristic(pdf, bsdf.pdf(chain.wi) * chain.chance);
        sum += f * chain.throughput * es.radiance * (weight / pdf);
    }
    return sum;
}

Vec3 PathIntegrator::causticFromLight(const Vertex& v, const Bsdf& bsdf, const Light& light,
                                      TraceContext& context) const {
    if (!v.inAir) return Vec3(0.0);
    Chains chains;
    const Vec3 toLight = glm::normalize(light.position() - v.si.point);
    const int count = glassChainsTo(v, {light.position(), Frame::fromAxis(toLight), -1, -1, false}, chains, context);
    Vec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        const Chain& chain = chains[static_cast<size_t>(i)];
        const double strength = strengthThrough(light, chain, toLight, v.pathLength);
        if (!(strength > 0)) continue;
        sum += bsdf.evalCos(chain.wi) * chain.throughput * light.colorToward(-chain.arrival) * strength;
    }
    return sum;
}

double PathIntegrator::strengthThrough(const Light& light, const Chain& chain, const Vec3& planeNormal,
                                       double pathLength) {
    // The light seen straight at the path's length lights the point as lightStrength says;
    // through the glass, the light of the solid angle it sends toward the path's end falls on
    // the area the path's beam has there, as the spread gives it (the étendue dA·cos θ·dω is
    // the same at both ends). The beam's area across it is the spread's times the cosine
    // between the path and the target plane's normal.
    const double across = chain.spread * std::abs(glm::dot(chain.arrival, planeNormal));
    if (!(across > 0)) return 0;
    return lightStrength(light, chain.length, pathLength) * chain.length * chain.length / across;
}

Vec3 PathIntegrator::causticFromAreaLight(const Vertex& v, const Bsdf& bsdf, const Light& light,
                                          const LightSample& ls, TraceContext& context) const {
    if (!v.inAir) return Vec3(0.0);
    const Vec3 normal = light.planeNormal();
    Chains chains;
    const int count = glassChainsTo(v, {ls.target, Frame::fromAxis(normal)}, chains, context);
    Vec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        const Chain& chain = chains[static_cast<size_t>(i)];
        // The sampled point lights as a point light does through the glass (the target plane
        // here the light's own), weighed against the bounces that meet the light by the same
        // path: light sampling's density of its direction is the point's by area times the
        // light's area per solid angle along the path.
        const Vec3 f = bsdf.evalCos(chain.wi);
        const double pdf = light.pointDensity() * chain.spread;
        const double strength = strengthThrough(light, chain, normal, v.pathLength);
        if (f == Vec3(0.0) || !(pdf > 0) || !(strength > 0)) continue;
        const double weight = powerHeuristic(pdf, bsdf.pdf(chain.wi) * chain.chance);
        sum += f * chain.throughput * ls.color * (strength * weight);
    }
    return sum;
}

double PathIntegrator::causticWeight(const CausticStart& start, const Vertex& v, TraceContext& context) const {
    const Vec3& from = start.from.si.point;
    const double pointDensity =
        areaDensity(emitters_.pdf(v.hit, from, v.si.point, v.si.normal), from, v.si.point, v.si.normal);
    return chainWeight(start, {v.si.point, Frame::fromAxis(v.si.normal), v.hit.primitive, v.hit.instance},
                       pointDensity, context);
}

double PathIntegrator::causticWeight(const CausticStart& start, const Light& light, const Vec3& point,
                                     TraceContext& context) const {
    return chainWeight(start, {point, Frame::fromAxis(light.planeNormal())}, light.pointDensity(), context);
}

double PathIntegrator::chainWeight(const CausticStart& start, const ChainTarget& target, double pointDensity,
                                   TraceContext& context) const {
    if (!(pointDensity > 0)) return 1;
    Chains chains;
    const int count = glassChainsTo(start.from, target, chains, context);
    for (int i = 0; i < count; ++i) {
        const Chain& chain = chains[static_cast<size_t>(i)];
        if (chain.crossings == start.crossings && glm::dot(chain.wi, start.dir) >= 1 - kSameDirection)
            return powerHeuristic(start.chance, pointDensity * chain.spread);
    }
    return 1;
}

} // namespace crt::tracer
