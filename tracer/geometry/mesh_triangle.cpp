// One triangle of a mesh, with interpolated vertex normals and UVs.
#include "tracer/geometry/mesh_triangle.hpp"

#include <utility>

namespace crt::tracer {

namespace {

template <class T> bool allValid(const int32_t (&idx)[3], const std::vector<T>& values) {
    for (int32_t i : idx)
        if (i < 0 || size_t(i) >= values.size()) return false;
    return true;
}

scene::TriangleShape shapeOf(const MeshData* mesh, size_t index) {
    if (!mesh || index >= mesh->triangles.size()) return {};
    const MeshData::Triangle& tri = mesh->triangles[index];
    if (!allValid(tri.v, mesh->positions)) return {};
    return {mesh->positions[size_t(tri.v[0])], mesh->positions[size_t(tri.v[1])],
            mesh->positions[size_t(tri.v[2])]};
}

} // namespace

MeshTriangleGeometry::MeshTriangleGeometry(std::shared_ptr<const MeshData> mesh, size_t index)
    : triangle_(shapeOf(mesh.get(), index)), mesh_(std::move(mesh)), index_(index) {
    if (mesh_ && index_ < mesh_->triangles.size()) {
        const MeshData::Triangle& tri = mesh_->triangles[index_];
        hasNormals_ = allValid(tri.n, mesh_->normals);
        hasUvs_ = allValid(tri.uv, mesh_->uvs);
    }
}

SurfacePoint MeshTriangleGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    SurfacePoint sp = triangle_.surfaceAt(ray, crossing, wantUv);
    if (woundInward()) sp.normal = sp.shadingNormal = -sp.normal;
    if (!hasNormals_ && !(hasUvs_ && wantUv)) return sp;
    const MeshData::Triangle& tri = mesh_->triangles[index_];
    Vec3 b = triangle_.barycentrics(ray, crossing);
    if (hasNormals_) {
        Vec3 n = b.x * mesh_->normals[size_t(tri.n[0])] + b.y * mesh_->normals[size_t(tri.n[1])] +
                 b.z * mesh_->normals[size_t(tri.n[2])];
        double len = glm::length(n);
        if (len > 0 && std::isfinite(len)) {
            sp.shadingNormal = n / len;
            // A solid's winding says which side is out; a surface's vertex normals do.
            if (glm::dot(sp.normal, sp.shadingNormal) < 0) {
                if (solid())
                    sp.shadingNormal = -sp.shadingNormal;
                else
                    sp.normal = -sp.normal;
            }
        }
    }
    if (hasUvs_ && wantUv) {
        const Vec2 uv[3] = {mesh_->uvs[size_t(tri.uv[0])], mesh_->uvs[size_t(tri.uv[1])],
                            mesh_->uvs[size_t(tri.uv[2])]};
        sp.uv = b.x * uv[0] + b.y * uv[1] + b.z * uv[2];
        tangentsFromUvs(tri, uv, sp);
    }
    return sp;
}

void MeshTriangleGeometry::tangentsFromUvs(const MeshData::Triangle& tri, const Vec2 (&uv)[3],
                                           SurfacePoint& sp) const {
    // The corners' positions and uvs relate by p − p2 = (u − u2)·dpdu + (v − v2)·dpdv (pbrt's
    // solution of that 2×2 system). Corners whose uvs are collinear parameterise nothing.
    const Vec3& p0 = mesh_->positions[size_t(tri.v[0])];
    const Vec3& p1 = mesh_->positions[size_t(tri.v[1])];
    const Vec3& p2 = mesh_->positions[size_t(tri.v[2])];
    Vec2 duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
    Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    double det = differenceOfProducts(duv02.x, duv12.y, duv02.y, duv12.x);
    if (!(std::abs(det) > 1e-12 * (sumAbs(Vec3(duv02, 0)) * sumAbs(Vec3(duv12, 0))))) {
        sp.dpdu = sp.dpdv = Vec3(0.0);
        return;
    }
    sp.dpdu = (duv12.y * dp02 - duv02.y * dp12) / det;
    sp.dpdv = (duv02.x * dp12 - duv12.x * dp02) / det;
}

} // namespace crt::tracer
