// A triangle mesh as one primitive: its BVH, line crossings and surface points.
#include "tracer/geometry/mesh.hpp"

#include "tracer/geometry/triangle.hpp"

#include <algorithm>

namespace crt::tracer {

namespace {

template <class T> bool allValid(const int32_t (&idx)[3], const std::vector<T>& values) {
    for (int32_t i : idx)
        if (i < 0 || size_t(i) >= values.size()) return false;
    return true;
}

/// Calls crossed(t, triangle, corners) for each triangle but `skipped` that the line crosses
/// within the BVH's search of (0, tMax), in the order the search meets them, until crossed
/// returns false (then false); tMax may shrink meanwhile (a nearest-hit search).
template <typename Crossed>
bool forEachCrossedTriangle(const TriangleMesh& mesh, const Ray& ray, const double& tMax, uint32_t skipped,
                            Crossed&& crossed) {
    const QuadRay quadRay(ray, mesh.frame());
    return mesh.bvh().traverseUncounted(LazyBoxRay(ray), tMax, [&](int32_t group) {
        const TriangleQuad& quad = mesh.quad(group);
        // The exact test for the triangles the line may cross, in the quad's order.
        for (int lanes = quad.mayCross(quadRay); lanes != 0; lanes &= lanes - 1) {
            const auto triangle = static_cast<uint32_t>(quad.triangle[__builtin_ctz(static_cast<unsigned>(lanes))]);
            if (triangle == skipped) continue;
            Vec3 p[3];
            mesh.corners(triangle, p);
            double t;
            Vec3 weights;
            if (crossTriangle(p, ray, t, weights) && !crossed(t, triangle, p)) return false;
        }
        return true;
    });
}

/// A crossing of one triangle while a closed mesh's crossings are gathered: whether the line
/// enters the solid there rides in the part's top bit until they are sorted and walked.
constexpr uint32_t kEnters = 1u << 31;

} // namespace

TriangleMesh::TriangleMesh(std::shared_ptr<const MeshData> data, unsigned threads)
    : data_(std::move(data)) {
    auto boundsOfCorners = [](const Vec3 (&p)[3]) {
        Bounds3 b = Bounds3::of(p[0], p[1]);
        b.include(p[2]);
        return b;
    };
    auto boundsOf = [&](size_t i) {
        Vec3 p[3];
        corners(static_cast<uint32_t>(i), p);
        return boundsOfCorners(p);
    };
    // A triangle is left out when a corner is out of range or not finite, or it has no area.
    auto drawable = [&](size_t i, Bounds3& b) {
        if (!allValid(data_->triangles[i].v, data_->positions)) return false;
        Vec3 p[3];
        corners(static_cast<uint32_t>(i), p);
        b = boundsOfCorners(p);
        const double area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
        return b.finite() && area > 0 && std::isfinite(area);
    };
    const size_t n = data_->triangles.size();
    std::vector<int32_t> ids; // the triangles the BVH holds, listed once one is left out
    bool leftOut = false;
    for (size_t i = 0; i < n; ++i) {
        Bounds3 b;
        const bool drawn = drawable(i, b);
        if (drawn) bounds_.include(b);
        if (!drawn && !leftOut) {
            leftOut = true;
            for (size_t k = 0; k < i; ++k) ids.push_back(static_cast<int32_t>(k));
        }
        if (drawn && leftOut) ids.push_back(static_cast<int32_t>(i));
    }
    // The frame's radius covers the rounding of its centre.
    frame_.centre = bounds_.centroid();
    const Vec3 reach = glm::max(bounds_.hi - frame_.centre, frame_.centre - bounds_.lo);
    frame_.radius = (1 + 0x1p-40) * std::max({reach.x, reach.y, reach.z, 0.0});
    auto makeQuad = [&](std::span<const int32_t> triangles) {
        quads_.push_back(makeTriangleQuad(frame_, triangles, [&](int32_t triangle, int k) {
            return data_->positions[static_cast<size_t>(data_->triangles[static_cast<size_t>(triangle)].v[k])];
        }));
        return static_cast<int32_t>(quads_.size() - 1);
    };
    auto keptBounds = [&](size_t item) { return boundsOf(static_cast<size_t>(ids[item])); };
    quads_.reserve(leftOut ? bvh_.buildGrouped(ids.size(), keptBounds, threads, ids)
                           : bvh_.buildGrouped(n, boundsOf, threads));
    bvh_.groupLeaves(makeQuad);
}

void MeshGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    out.count = 0;
    out.startsInside = false;
    // The BVH is searched on (0, tMax): from a point before the mesh's bounds, so that the
    // whole line through them is.
    const Bounds3& b = mesh_->bounds();
    LineSpan span;
    if (b.empty() || !lineSpan(ray, b.lo, b.hi, span)) return;
    const double start = span.enter - 0.5 * (span.exit - span.enter) - 1;
    const Ray from{ray.at(start), ray.dir};
    const double length = 2 * (span.exit - start) + 1;
    const bool closed = solid();
    const bool inward = mesh_->data().inward;
    forEachCrossedTriangle(*mesh_, from, length, kNoPart, [&](double t, uint32_t triangle, const Vec3 (&p)[3]) {
        uint32_t part = triangle;
        if (closed) {
            // Against the outward normal: the right-hand one, or the left-hand one inward.
            const double facing = glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), ray.dir);
            if ((facing < 0) != inward) part |= kEnters;
        }
        out.add(start + t, part);
        return true;
    });
    Crossing* first = &out[0];
    // At one t, entries before exits: a line grazing the silhouette along an edge enters and
    // leaves there, and the other order would skip the exit and stay inside.
    std::sort(first, first + out.count, [](const Crossing& a, const Crossing& c) {
        return a.t != c.t ? a.t < c.t : (a.part & kEnters) > (c.part & kEnters);
    });
    if (!closed) return;
    int kept = 0;
    bool inside = false;
    for (int i = 0; i < out.count; ++i) {
        const bool enters = (out[i].part & kEnters) != 0;
        if (enters == inside) continue; // the same step again, at an edge
        inside = enters;
        out[kept++] = {out[i].t, out[i].part & ~kEnters};
    }
    out.count = kept;
}

bool MeshGeometry::crossingsIn(const Ray& ray, double tMin, double tMax, CrossingVisitor visit,
                               uint32_t skippedPart) const {
    return forEachCrossedTriangle(*mesh_, ray, tMax, skippedPart, [&](double t, uint32_t triangle, const Vec3 (&)[3]) {
        return !(t > tMin && t < tMax) || visit(Crossing{t, triangle});
    });
}

bool MeshGeometry::firstCrossingIn(const Ray& ray, double tMin, double tMax, Crossing& out,
                                   uint32_t skippedPart) const {
    double nearest = tMax; // the traversal skips what lies beyond it as it shrinks
    bool found = false;
    forEachCrossedTriangle(*mesh_, ray, nearest, skippedPart, [&](double t, uint32_t triangle, const Vec3 (&)[3]) {
        if (t > tMin && t < nearest) {
            nearest = t;
            out = {t, triangle};
            found = true;
        }
        return true;
    });
    return found;
}

SurfacePoint MeshGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    const MeshData& data = mesh_->data();
    Vec3 corners[3];
    mesh_->corners(crossing.part, corners);
    const TriangleGeometry face(scene::TriangleShape{corners[0], corners[1], corners[2]});
    SurfacePoint sp = face.surfaceAt(ray, crossing, wantUv);
    if (solid() && data.inward) sp.normal = sp.shadingNormal = -sp.normal;
    const MeshData::Triangle& tri = data.triangles[crossing.part];
    const bool hasNormals = allValid(tri.n, data.normals);
    const bool hasUvs = wantUv && allValid(tri.uv, data.uvs);
    if (!hasNormals && !hasUvs) return sp;
    const Vec3 b = face.barycentrics(ray, crossing);
    if (hasNormals) {
        Vec3 n = b.x * data.normals[size_t(tri.n[0])] + b.y * data.normals[size_t(tri.n[1])] +
                 b.z * data.normals[size_t(tri.n[2])];
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
    if (hasUvs) {
        const Vec2 uv[3] = {data.uvs[size_t(tri.uv[0])], data.uvs[size_t(tri.uv[1])],
                            data.uvs[size_t(tri.uv[2])]};
        sp.uv = b.x * uv[0] + b.y * uv[1] + b.z * uv[2];
        tangentsFromUvs(tri, uv, sp);
    }
    return sp;
}

void MeshGeometry::tangentsFromUvs(const MeshData::Triangle& tri, const Vec2 (&uv)[3],
                                   SurfacePoint& sp) const {
    // The corners' positions and uvs relate by p − p2 = (u − u2)·dpdu + (v − v2)·dpdv (pbrt's
    // solution of that 2×2 system). Corners whose uvs are collinear parameterise nothing.
    const MeshData& data = mesh_->data();
    const Vec3& p0 = data.positions[size_t(tri.v[0])];
    const Vec3& p1 = data.positions[size_t(tri.v[1])];
    const Vec3& p2 = data.positions[size_t(tri.v[2])];
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
