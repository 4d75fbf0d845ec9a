// Emitting surfaces chosen by power, points on them by area.
#include "tracer/emitters.hpp"

#include "tracer/lights.hpp"

#include <algorithm>
#include <optional>

namespace crt::tracer {

namespace {

/// 1 − cos θmax of the cone a sphere of radius r fills from a distance d > r, without the
/// cancellation of 1 − √(1 − r²/d²) for small spheres far away.
double oneMinusCosMax(double r, double d) {
    const double sin2 = (r / d) * (r / d);
    return sin2 / (1 + std::sqrt(std::max(0.0, 1 - sin2)));
}

/// The scale of a linear map that is a similarity (rotation and uniform scale), or 0.
double similarityScale(const glm::dmat3& linear) {
    const glm::dmat3 gram = glm::transpose(linear) * linear;
    const double scale2 = gram[0][0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(gram[i][j] - (i == j ? scale2 : 0.0)) > 1e-12 * scale2) return 0;
    return std::sqrt(scale2);
}

/// The index i with cumulative[i] <= pick < cumulative[i + 1].
size_t pickIndex(const std::vector<double>& cumulative, double pick) {
    const auto at = std::upper_bound(cumulative.begin() + 1, cumulative.end(), pick);
    return std::min(static_cast<size_t>(at - cumulative.begin()) - 1, cumulative.size() - 2);
}

} // namespace

double Emitters::coneSolidAngle(const Source& s, const Vec3& from) {
    const double d = glm::length(s.center - from);
    return d > s.radius * (1 + 1e-9) ? 2 * kPi * oneMinusCosMax(s.radius, d) : 0;
}

void Emitters::placeCone(Source& s, const SphereGeometry& sphere) {
    Vec3 center = sphere.center();
    double radius = sphere.radius();
    // Only a similarity keeps a sphere a sphere: rotation, translation, uniform scale.
    for (const TransformPair* transform : {s.shape, s.drawing}) {
        if (!transform) continue;
        const double scale = similarityScale(transform->toWorld.linear());
        if (!(scale > 0)) return;
        center = transform->toWorld.point(center);
        radius *= scale;
    }
    s.center = center;
    s.radius = radius;
}

std::vector<Emitters::Candidate> Emitters::candidatesOf(const RenderScene& owner) const {
    std::vector<bool> inCsg(owner.primitives.size(), false);
    for (const CsgTreeNode& node : owner.csgNodes)
        if (node.kind == CsgNodeKind::Leaf && node.primitive >= 0) inCsg[static_cast<size_t>(node.primitive)] = true;
    std::vector<Candidate> candidates;
    for (size_t p = 0; p < owner.primitives.size(); ++p) {
        const Primitive& primitive = owner.primitives[p];
        if (primitive.transform >= RenderScene::kFirstMovingTransform) continue;
        if (primitive.material >= 0) {
            const ShadingMaterial& m = scene_.materials[static_cast<size_t>(primitive.material)];
            if (m.blend >= 0 || !(luminance(rgb(m.emission)) > 0)) continue;
        }
        candidates.push_back({static_cast<int32_t>(p), inCsg[p]});
    }
    return candidates;
}

int32_t Emitters::faceTableOf(const TriangleMesh& mesh, double& area) {
    const auto [known, added] = faceTableOfMesh_.emplace(&mesh, static_cast<int32_t>(faceTables_.size()));
    if (added) {
        std::vector<double> areas;
        areas.reserve(mesh.data().triangles.size());
        for (uint32_t face = 0; face < mesh.data().triangles.size(); ++face) {
            Vec3 corners[3];
            mesh.corners(face, corners);
            areas.push_back(triangleArea(corners));
        }
        faceTables_.emplace_back(std::move(areas));
    }
    const Distribution1D& faces = faceTables_[static_cast<size_t>(known->second)];
    area = faces.mean() * static_cast<double>(faces.size());
    return known->second;
}

void Emitters::addSources(const RenderScene& owner, int32_t instance, const std::vector<Candidate>& candidates,
                          std::vector<double>& power) {
    const TransformPair* drawing = nullptr;
    int32_t drawingMaterial = -1;
    if (instance >= 0) {
        const Instance& drawn = scene_.instances[static_cast<size_t>(instance)];
        if (drawn.transform >= RenderScene::kFirstMovingTransform) return;
        if (drawn.transform >= 0) drawing = &scene_.transforms[static_cast<size_t>(drawn.transform)];
        drawingMaterial = drawn.material;
    }
    for (const Candidate& candidate : candidates) {
        const Primitive& primitive = owner.primitives[static_cast<size_t>(candidate.primitive)];
        const int32_t material = primitive.material >= 0 ? primitive.material : drawingMaterial;
        if (material < 0) continue;
        const ShadingMaterial& m = scene_.materials[static_cast<size_t>(material)];
        const double glow = luminance(rgb(m.emission));
        if (m.blend >= 0 || !(glow > 0)) continue;
        Source s;
        s.instance = instance;
        s.primitive = candidate.primitive;
        s.geometry = &primitive.geometry;
        s.shape = primitive.transform >= 0 ? &owner.transforms[static_cast<size_t>(primitive.transform)] : nullptr;
        s.drawing = drawing;
        s.mayBeCarved = candidate.inCsg;
        s.radiance = rgb(m.emission);
        if (const MeshGeometry* mesh = shapeIf<MeshGeometry>(primitive.geometry)) {
            s.faces = faceTableOf(mesh->mesh(), s.objectArea);
        } else {
            s.objectArea = sampledArea(primitive.geometry);
            if (const SphereGeometry* sphere = shapeIf<SphereGeometry>(primitive.geometry)) placeCone(s, *sphere);
        }
        if (!(s.objectArea > 0)) continue;
        // Power is only the chance of being chosen: the transforms' scale is taken as uniform.
        double scale2 = 1;
        for (const TransformPair* transform : {s.shape, s.drawing})
            if (transform) scale2 *= std::pow(std::abs(glm::determinant(transform->toWorld.linear())), 2.0 / 3.0);
        const auto index = static_cast<int32_t>(sources_.size());
        if (instance < 0) {
            if (sourceOfPrimitive_.empty()) sourceOfPrimitive_.assign(owner.primitives.size(), -1);
            sourceOfPrimitive_[static_cast<size_t>(s.primitive)] = index;
        } else {
            sourceOfInstancePart_.emplace(key(instance, s.primitive), index);
        }
        sources_.push_back(s);
        power.push_back(glow * s.objectArea * scale2);
    }
}

Emitters::Emitters(const RenderScene& scene) : scene_(scene) {
    std::vector<double> power;
    addSources(scene, -1, candidatesOf(scene), power);
    // A prototype's candidates are found once, however often it is drawn.
    std::vector<std::optional<std::vector<Candidate>>> prototypeCandidates(scene.prototypes.size());
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const size_t prototype = static_cast<size_t>(scene.instances[i].prototype);
        if (!prototypeCandidates[prototype]) prototypeCandidates[prototype] = candidatesOf(*scene.prototypes[prototype]);
        addSources(*scene.prototypes[prototype], static_cast<int32_t>(i), *prototypeCandidates[prototype], power);
    }
    double total = 0;
    cumulative_.assign(1, 0.0);
    for (double w : power) cumulative_.push_back(total += w);
    for (double& c : cumulative_) c /= total;
}

double Emitters::areaDensity(const Source& s, const Vec3& normal) {
    // The area of a world element over the area of the object element it comes from, through
    // the instance's transform and then the primitive's.
    double toObject = 1;
    Vec3 n = normal;
    if (s.drawing) {
        toObject *= s.drawing->toObject.areaScale(n);
        n = s.drawing->toObject.normal(n);
    }
    if (s.shape) toObject *= s.shape->toObject.areaScale(n);
    return toObject / s.objectArea;
}

AreaSample Emitters::pointOn(const Source& s, const Vec2& u) const {
    AreaSample point;
    if (s.faces >= 0) {
        // The face by its share of the area, then where u.x fell within that share, stretched
        // over [0, 1).
        const Distribution1D& faces = faceTables_[static_cast<size_t>(s.faces)];
        size_t face = 0;
        double pdf = 0;
        const double x = faces.sample(u.x, face, pdf) * static_cast<double>(faces.size());
        const double along = std::clamp(x - static_cast<double>(face), 0.0, std::nextafter(1.0, 0.0));
        Vec3 corners[3];
        shapeIf<MeshGeometry>(*s.geometry)->mesh().corners(static_cast<uint32_t>(face), corners);
        point = sampleTriangle(corners, {along, u.y});
    } else {
        point = sampleArea(*s.geometry, u);
    }
    for (const TransformPair* transform : {s.shape, s.drawing})
        if (transform) point = {transform->toWorld.point(point.point), transform->toWorld.normal(point.normal)};
    return point;
}

bool Emitters::sample(const Vec3& from, double pick, const Vec2& u, EmitterSample& out) const {
    if (sources_.empty()) return false;
    const size_t index = pickIndex(cumulative_, pick);
    const Source& s = sources_[index];
    out.mayBeCarved = s.mayBeCarved;
    out.primitive = s.primitive;
    out.instance = s.instance;
    out.radiance = s.radiance;
    if (s.radius > 0) {
        if (const double solidAngle = coneSolidAngle(s, from); solidAngle > 0) {
            // A direction uniform in the cone, and where it meets the sphere's near side.
            const Vec3 toCenter = s.center - from;
            const double d = glm::length(toCenter);
            const double cosTheta = 1 - u.x * oneMinusCosMax(s.radius, d);
            const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), phi = 2 * kPi * u.y;
            const Vec3 dir = Frame::fromAxis(toCenter / d).fromLocal({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
            const double t = d * cosTheta - std::sqrt(std::max(0.0, s.radius * s.radius - d * d * sinTheta * sinTheta));
            out.point = from + t * dir;
            out.normal = glm::normalize(out.point - s.center);
            out.pdf = chance(index) / solidAngle;
            return true;
        }
    }
    const AreaSample point = pointOn(s, u);
    out.pdf = areaSolidAngleDensity(index, from, point.point, point.normal);
    if (!(out.pdf > 0)) return false;
    out.point = point.point;
    out.normal = point.normal;
    return true;
}

double Emitters::areaSolidAngleDensity(size_t index, const Vec3& from, const Vec3& point, const Vec3& normal) const {
    const Vec3 offset = point - from;
    const double distance2 = glm::dot(offset, offset);
    const double cosLight = std::abs(glm::dot(normal, offset)) / std::sqrt(distance2);
    if (!(distance2 > 0) || cosLight <= 0) return 0;
    return chance(index) * areaDensity(sources_[index], normal) * distance2 / cosLight;
}

double Emitters::pdf(const Hit& hit, const Vec3& from, const Vec3& point, const Vec3& normal) const {
    if (hit.primitive < 0) return 0;
    int32_t source = -1;
    if (hit.instance < 0) {
        if (!sourceOfPrimitive_.empty()) source = sourceOfPrimitive_[static_cast<size_t>(hit.primitive)];
    } else if (const auto found = sourceOfInstancePart_.find(key(hit.instance, hit.primitive));
               found != sourceOfInstancePart_.end()) {
        source = found->second;
    }
    if (source < 0) return 0;
    const size_t index = static_cast<size_t>(source);
    const Source& s = sources_[index];
    if (s.radius > 0) {
        if (const double solidAngle = coneSolidAngle(s, from); solidAngle > 0) {
            // The cone reaches only the cap of the sphere seen from `from`: a path that meets
            // the rest (through a gap a CSG tree cut, or through the sphere) went where light
            // sampling never goes.
            const bool seen = glm::dot(point - s.center, from - s.center) >= s.radius * s.radius * (1 - 1e-6);
            return seen ? chance(index) / solidAngle : 0;
        }
    }
    return areaSolidAngleDensity(index, from, point, normal);
}

} // namespace crt::tracer
