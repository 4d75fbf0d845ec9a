// Whether a triangle mesh bounds a solid (see mesh_closure.hpp).
#include "scene/mesh_closure.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

namespace crt::scene {

namespace {

/// One side of an edge: its corners in the triangle's order.
struct HalfEdge {
    int32_t from, to;
    uint64_t key() const {
        const auto [lo, hi] = std::minmax(from, to);
        return (uint64_t(uint32_t(lo)) << 32) | uint32_t(hi);
    }
};

} // namespace

std::vector<int32_t> firstVertexAtPosition(const std::vector<glm::dvec3>& positions) {
    const size_t n = positions.size();
    std::vector<int32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto less = [&](int32_t a, int32_t b) {
        const glm::dvec3 &p = positions[a], &q = positions[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<int32_t> first(n);
    for (size_t i = 0; i < n; ++i) {
        const bool same = i > 0 && positions[order[i]] == positions[order[i - 1]];
        first[order[i]] = same ? first[order[i - 1]] : order[i];
    }
    return first;
}

MeshClosure meshClosure(const MeshData& mesh) {
    MeshClosure result;
    const std::vector<int32_t> welded = firstVertexAtPosition(mesh.positions);
    std::vector<HalfEdge> edges;
    edges.reserve(3 * mesh.triangles.size());
    double volume = 0;
    for (const MeshData::Triangle& t : mesh.triangles) {
        const int32_t v[3] = {welded[t.v[0]], welded[t.v[1]], welded[t.v[2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int k = 0; k < 3; ++k) edges.push_back({v[k], v[(k + 1) % 3]});
        const glm::dvec3 &a = mesh.positions[v[0]], &b = mesh.positions[v[1]],
                         &c = mesh.positions[v[2]];
        volume += glm::dot(a, glm::cross(b, c));
    }
    if (edges.empty()) {
        result.problem = "has no triangles";
        return result;
    }
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& a, const HalfEdge& b) {
        return a.key() != b.key() ? a.key() < b.key() : a.from < b.from;
    });
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edges[j].key() == edges[i].key()) ++j;
        const size_t count = j - i;
        std::string problem;
        if (count == 1)
            problem = "has one triangle";
        else if (count > 2)
            problem = "has " + std::to_string(count) + " triangles";
        else if (edges[i].from == edges[i + 1].from)
            problem = "runs the same way in both of its triangles";
        if (!problem.empty()) {
            result.edgeFrom = edges[i].from;
            result.edgeTo = edges[i].to;
            result.problem = std::move(problem);
            return result;
        }
        i = j;
    }
    result.closed = true;
    result.inward = volume < 0;
    return result;
}

MeshClosure markClosure(MeshData& mesh) {
    MeshClosure closure = meshClosure(mesh);
    mesh.closed = closure.closed;
    mesh.inward = closure.inward;
    return closure;
}

} // namespace crt::scene
