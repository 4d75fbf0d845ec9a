// Emitting surfaces chosen by power, points on them by area.
#include "tracer/emitters.hpp"

#include "tracer/lights.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

/// 1 − cos θmax of the cone a sphere of radius r fills from a distance d > r, without the
/// cancellation of 1 − √(1 − r²/d²) for small spheres far away.
double oneMinusCosMax(double r, double d) {
    const double sin2 = (r / d) * (r / d);
    return sin2 / (1 + std::sqrt(std::max(0.0, 1 - sin2)));
}

} // namespace

double Emitters::coneSolidAngle(const Entry& e, const Vec3& from) {
    const double d = glm::length(e.center - from);
    return d > e.radius * (1 + 1e-9) ? 2 * kPi * oneMinusCosMax(e.radius, d) : 0;
}

void Emitters::placeCone(Entry& e, const SphereGeometry& sphere) const {
    const Primitive& primitive = scene_.primitives[static_cast<size_t>(e.primitive)];
    Vec3 center = sphere.center();
    double radius = sphere.radius();
    if (primitive.transform >= 0) {
        // Only a similarity keeps a sphere a sphere: rotation, translation, uniform scale.
        const Transform& toWorld = scene_.transforms[static_cast<size_t>(primitive.transform)].toWorld;
        const glm::dmat3 gram = glm::transpose(toWorld.linear()) * toWorld.linear();
        const double scale2 = gram[0][0];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (std::abs(gram[i][j] - (i == j ? scale2 : 0.0)) > 1e-12 * scale2) return;
        center = toWorld.point(center);
        radius *= std::sqrt(scale2);
    }
    e.center = center;
    e.radius = radius;
}

Emitters::Emitters(const RenderScene& scene) : scene_(scene) {
    std::vector<bool> inCsg(scene.primitives.size(), false);
    for (const CsgTreeNode& node : scene.csgNodes)
        if (node.kind == CsgNodeKind::Leaf && node.primitive >= 0) inCsg[static_cast<size_t>(node.primitive)] = true;
    std::vector<double> power;
    for (size_t p = 0; p < scene.primitives.size(); ++p) {
        const Primitive& primitive = scene.primitives[p];
        if (inCsg[p] || primitive.material < 0 || primitive.transform >= RenderScene::kFirstMovingTransform) continue;
        const ShadingMaterial& m = scene.materials[static_cast<size_t>(primitive.material)];
        const double glow = luminance(rgb(m.emission));
        if (m.blend >= 0 || glow <= 0) continue;
        // Power is only the chance of being chosen: the transform's scale is taken as uniform.
        const double scale =
            primitive.transform >= 0
                ? std::cbrt(std::abs(glm::determinant(scene.transforms[static_cast<size_t>(primitive.transform)].toWorld.linear())))
                : 1.0;
        auto add = [&](uint32_t face, double area) {
            if (!(area > 0)) return;
            if (firstEntryOf_.empty()) firstEntryOf_.assign(scene.primitives.size(), -1);
            if (firstEntryOf_[p] < 0) firstEntryOf_[p] = static_cast<int32_t>(entries_.size());
            entries_.push_back({static_cast<int32_t>(p), face, area});
            if (const SphereGeometry* sphere = shapeIf<SphereGeometry>(primitive.geometry)) placeCone(entries_.back(), *sphere);
            power.push_back(glow * area * scale * scale);
        };
        if (const MeshGeometry* mesh = shapeIf<MeshGeometry>(primitive.geometry)) {
            const TriangleMesh& tm = mesh->mesh();
            for (uint32_t face = 0; face < tm.data().triangles.size(); ++face) {
                Vec3 corners[3];
                tm.corners(face, corners);
                add(face, triangleArea(corners));
            }
            continue;
        }
        add(kNoPart, sampledArea(primitive.geometry));
    }
    double total = 0;
    cumulative_.assign(1, 0.0);
    for (double w : power) cumulative_.push_back(total += w);
    for (double& c : cumulative_) c /= total;
}

double Emitters::areaDensity(const Entry& e, const Vec3& normal) const {
    const int32_t transform = scene_.primitives[static_cast<size_t>(e.primitive)].transform;
    const double toObject =
        transform >= 0 ? scene_.transforms[static_cast<size_t>(transform)].toObject.areaScale(normal) : 1.0;
    return toObject / e.objectArea;
}

bool Emitters::sample(const Vec3& from, double pick, const Vec2& u, EmitterSample& out) const {
    if (entries_.empty()) return false;
    const auto at = std::upper_bound(cumulative_.begin() + 1, cumulative_.end(), pick);
    const size_t index = std::min(static_cast<size_t>(at - cumulative_.begin()) - 1, entries_.size() - 1);
    const Entry& e = entries_[index];
    const Primitive& primitive = scene_.primitives[static_cast<size_t>(e.primitive)];
    if (e.radius > 0) {
        if (const double solidAngle = coneSolidAngle(e, from); solidAngle > 0) {
            // A direction uniform in the cone, and where it meets the sphere's near side.
            const Vec3 toCenter = e.center - from;
            const double d = glm::length(toCenter);
            const double cosTheta = 1 - u.x * oneMinusCosMax(e.radius, d);
            const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), phi = 2 * kPi * u.y;
            const Vec3 dir = Frame::fromAxis(toCenter / d).fromLocal({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
            const double t = d * cosTheta - std::sqrt(std::max(0.0, e.radius * e.radius - d * d * sinTheta * sinTheta));
            out.point = from + t * dir;
            out.normal = glm::normalize(out.point - e.center);
            out.radiance = rgb(scene_.materials[static_cast<size_t>(primitive.material)].emission);
            out.pdf = chance(index) / solidAngle;
            return true;
        }
    }
    AreaSample point;
    if (const MeshGeometry* mesh = shapeIf<MeshGeometry>(primitive.geometry)) {
        Vec3 corners[3];
        mesh->mesh().corners(e.face, corners);
        point = sampleTriangle(corners, u);
    } else {
        point = sampleArea(primitive.geometry, u);
    }
    if (primitive.transform >= 0) {
        const Transform& toWorld = scene_.transforms[static_cast<size_t>(primitive.transform)].toWorld;
        point = {toWorld.point(point.point), toWorld.normal(point.normal)};
    }
    out.pdf = areaSolidAngleDensity(index, from, point.point, point.normal);
    if (!(out.pdf > 0)) return false;
    out.point = point.point;
    out.normal = point.normal;
    out.radiance = rgb(scene_.materials[static_cast<size_t>(primitive.material)].emission);
    return true;
}

double Emitters::areaSolidAngleDensity(size_t index, const Vec3& from, const Vec3& point, const Vec3& normal) const {
    const Vec3 offset = point - from;
    const double distance2 = glm::dot(offset, offset);
    const double cosLight = std::abs(glm::dot(normal, offset)) / std::sqrt(distance2);
    if (!(distance2 > 0) || cosLight <= 0) return 0;
    return chance(index) * areaDensity(entries_[index], normal) * distance2 / cosLight;
}

double Emitters::pdf(const Hit& hit, const Vec3& from, const Vec3& point, const Vec3& normal) const {
    if (firstEntryOf_.empty() || hit.instance >= 0 || hit.primitive < 0) return 0;
    int32_t first = firstEntryOf_[static_cast<size_t>(hit.primitive)];
    if (first < 0) return 0;
    const size_t index = static_cast<size_t>(first) + (entries_[static_cast<size_t>(first)].face == kNoPart ? 0 : hit.crossing.part);
    if (index >= entries_.size() || entries_[index].primitive != hit.primitive) return 0;
    if (entries_[index].radius > 0)
        if (const double solidAngle = coneSolidAngle(entries_[index], from); solidAngle > 0)
            return chance(index) / solidAngle;
    return areaSolidAngleDensity(index, from, point, normal);
}

} // namespace crt::tracer
