// Whether a triangle mesh bounds a solid (see mesh_closure.hpp).
#include "scene/mesh_closure.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <numeric>
#include <utility>
#include <vector>

namespace crt::scene {

namespace {

/// One side of an edge, in one number ordered as (smaller corner, larger corner, corner it
/// runs from) are: the smaller vertex number in bits 32-62, the larger in bits 1-31, and bit 0
/// set when the triangle runs the edge from the larger. Vertex numbers are below 2^31.
uint64_t halfEdge(int32_t from, int32_t to) {
    const auto [lo, hi] = std::minmax(from, to);
    return uint64_t(uint32_t(lo)) << 32 | uint64_t(uint32_t(hi)) << 1 | uint64_t(from == hi);
}
uint64_t edgeOf(uint64_t halfEdge) { return halfEdge >> 1; }
int32_t fromOf(uint64_t halfEdge) {
    const auto lo = int32_t(halfEdge >> 32), hi = int32_t((halfEdge >> 1) & 0x7fffffff);
    return (halfEdge & 1) ? hi : lo;
}
int32_t toOf(uint64_t halfEdge) { return fromOf(halfEdge ^ 1); }

/// Sorts in place: each value goes to the bucket of its 16 highest significant bits (one pass
/// of swaps, as American flag sort makes), then each bucket is sorted on its own. A large
/// mesh has millions of half edges; bucketed first, each comparison sort has a few dozen, and
/// no copy of them all is needed, as a radix sort would.
void sortHalfEdges(std::vector<uint64_t>& values) {
    uint64_t bits = 0;
    for (uint64_t v : values) bits |= v;
    const int shift = std::max(static_cast<int>(std::bit_width(bits)) - 16, 0);
    auto bucket = [shift](uint64_t v) { return static_cast<size_t>(v >> shift); };
    std::vector<size_t> end(size_t{1} << 16);
    for (uint64_t v : values) ++end[bucket(v)];
    std::inclusive_scan(end.begin(), end.end(), end.begin());
    std::vector<size_t> next(end.size());
    std::copy(end.begin(), end.end() - 1, next.begin() + 1);
    const std::vector<size_t> begin = next;
    for (size_t b = 0; b < end.size(); ++b) {
        while (next[b] < end[b]) {
            uint64_t v = values[next[b]];
            for (size_t home = bucket(v); home != b; home = bucket(v)) std::swap(v, values[next[home]++]);
            values[next[b]++] = v;
        }
        const auto first = values.begin() + static_cast<std::ptrdiff_t>(begin[b]);
        std::sort(first, values.begin() + static_cast<std::ptrdiff_t>(end[b]));
    }
}

} // namespace

std::vector<int32_t> firstVertexAtPosition(const std::vector<glm::dvec3>& positions) {
    // Vertices in number order into a hash table of the first at each position (open
    // addressing, at most half full): equal positions (==, so -0 is 0 and NaN is nothing)
    // meet at the first vertex found there.
    const size_t n = positions.size();
    const size_t slots = std::bit_ceil(std::max<size_t>(2 * n, 16));
    std::vector<int32_t> table(slots, -1);
    auto hash = [](const glm::dvec3& p) {
        uint64_t h = 0;
        for (int axis = 0; axis < 3; ++axis) // + 0.0 makes -0 the +0 it equals
            h = (h ^ std::bit_cast<uint64_t>(p[axis] + 0.0)) * 0x9e3779b97f4a7c15u;
        return static_cast<size_t>(h ^ (h >> 29));
    };
    std::vector<int32_t> first(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& p = positions[i];
        size_t slot = hash(p) & (slots - 1);
        while (table[slot] >= 0 && positions[static_cast<size_t>(table[slot])] != p) slot = (slot + 1) & (slots - 1);
        if (table[slot] < 0) table[slot] = static_cast<int32_t>(i);
        first[i] = table[slot];
    }
    return first;
}

MeshClosure meshClosure(const MeshData& mesh) {
    MeshClosure result;
    const std::vector<int32_t> welded = firstVertexAtPosition(mesh.positions);
    std::vector<uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    double volume = 0;
    for (const MeshData::Triangle& t : mesh.triangles) {
        const int32_t v[3] = {welded[t.v[0]], welded[t.v[1]], welded[t.v[2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int k = 0; k < 3; ++k) edges.push_back(halfEdge(v[k], v[(k + 1) % 3]));
        const glm::dvec3 &a = mesh.positions[v[0]], &b = mesh.positions[v[1]],
                         &c = mesh.positions[v[2]];
        volume += glm::dot(a, glm::cross(b, c));
    }
    if (edges.empty()) {
        result.problem = "has no triangles";
        return result;
    }
    sortHalfEdges(edges);
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edgeOf(edges[j]) == edgeOf(edges[i])) ++j;
        const size_t count = j - i;
        std::string problem;
        if (count == 1)
            problem = "has one triangle";
        else if (count > 2)
            problem = "has " + std::to_string(count) + " triangles";
        else if (edges[i] == edges[i + 1])
            problem = "runs the same way in both of its triangles";
        if (!problem.empty()) {
            result.edgeFrom = fromOf(edges[i]);
            result.edgeTo = toOf(edges[i]);
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
