// Emitting surfaces chosen by power, points on them by area.
#include "tracer/emitters.hpp"

#include "tracer/lights.hpp"

#include <algorithm>

namespace crt::tracer {

Emitters::Emitters(const RenderScene& scene) : scene_(scene) {
    std::vector<bool> inCsg(scene.primitives.size(), false);
    for (const CsgTreeNode& node : scene.csgNodes)
        if (node.kind == CsgNodeKind::Leaf && node.primitive >= 0) inCsg[static_cast<size_t>(node.primitive)] = true;
    std::vector<double> power;
    for (size_t p = 0; p < scene.primitives.size(); ++p) {
        const Primitive& primitive = scene.primitives[p];
        if (inCsg[p] || primitive.material < 0) continue;
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
    const Vec3 offset = point.point - from;
    const double distance2 = glm::dot(offset, offset);
    const double cosLight = std::abs(glm::dot(point.normal, offset)) / std::sqrt(distance2);
    if (!(distance2 > 0) || cosLight <= 0) return false;
    out.point = point.point;
    out.normal = point.normal;
    out.radiance = rgb(scene_.materials[static_cast<size_t>(primitive.material)].emission);
    out.pdf = chance(index) * areaDensity(e, point.normal) * distance2 / cosLight;
    return true;
}

double Emitters::pdf(const Hit& hit, const Vec3& from, const Vec3& point, const Vec3& normal) const {
    if (firstEntryOf_.empty() || hit.instance >= 0 || hit.primitive < 0) return 0;
    int32_t first = firstEntryOf_[static_cast<size_t>(hit.primitive)];
    if (first < 0) return 0;
    const size_t index = static_cast<size_t>(first) + (entries_[static_cast<size_t>(first)].face == kNoPart ? 0 : hit.crossing.part);
    if (index >= entries_.size() || entries_[index].primitive != hit.primitive) return 0;
    const Vec3 offset = point - from;
    const double distance2 = glm::dot(offset, offset);
    const double cosLight = std::abs(glm::dot(normal, offset)) / std::sqrt(distance2);
    if (!(distance2 > 0) || cosLight <= 0) return 0;
    return chance(index) * areaDensity(entries_[index], normal) * distance2 / cosLight;
}

} // namespace crt::tracer
