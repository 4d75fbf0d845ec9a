// Whether a triangle mesh bounds a solid (see mesh_closure.hpp).
#include "scene/mesh_closure.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace crt::scene {

namespace {

/// Calls visit(v) for each triangle whose corners, welded by position (`welded`), are three
/// vertices v[0], v[1], v[2]: the others have no area.
template <typename Visit>
void forEachWeldedTriangle(const MeshData& mesh, const std::vector<int32_t>& welded,
                           Visit&& visit) {
    for (const MeshData::Triangle& t : mesh.triangles) {
        const int32_t v[3] = {welded[t.v[0]], welded[t.v[1]], welded[t.v[2]]};
        if (v[0] != v[1] && v[1] != v[2] && v[2] != v[0]) visit(v);
    }
}

/// The half edges of those triangles gathered at their smaller corner, vertex by vertex: a
/// compressed sparse row list. Each is one number ordered as (larger corner, corner it runs
/// from) are: the larger vertex number times two, plus 1 when the triangle runs the edge from
/// the larger (vertex numbers are below 2^31). A large mesh has millions of half edges;
/// gathered so, they are sorted a few at a time, and walked in vertex order they come in the
/// order of (smaller corner, larger corner, corner it runs from).
class HalfEdgesByCorner {
  public:
    HalfEdgesByCorner(const MeshData& mesh, const std::vector<int32_t>& welded)
        : first_(mesh.positions.size() + 1, 0) {
        auto forEachEdge = [&](auto&& visit) {
            forEachWeldedTriangle(mesh, welded, [&](const int32_t(&v)[3]) {
                for (int k = 0; k < 3; ++k) visit(v[k], v[(k + 1) % 3]);
            });
        };
        forEachEdge(
            [&](int32_t from, int32_t to) { ++first_[static_cast<size_t>(std::min(from, to))]; });
        // Counted up to each vertex, then each list filled from its end, which leaves its start.
        std::inclusive_scan(first_.begin(), first_.end(), first_.begin());
        sides_ = std::make_unique_for_overwrite<uint32_t[]>(first_.back());
        forEachEdge([&](int32_t from, int32_t to) {
            const auto [smaller, larger] = std::minmax(from, to);
            sides_[--first_[static_cast<size_t>(smaller)]] =
                uint32_t(larger) << 1 | uint32_t(from == larger);
        });
    }

    bool empty() const { return first_.back() == 0; }
    size_t vertices() const { return first_.size() - 1; }
    /// The half edges whose smaller corner is `v`, sorted.
    std::span<const uint32_t> sortedAt(size_t v) {
        uint32_t *begin = sides_.get() + first_[v], *end = sides_.get() + first_[v + 1];
        std::sort(begin, end);
        return {begin, end};
    }

    static int32_t larger(uint32_t side) { return static_cast<int32_t>(side >> 1); }
    static bool runsFromLarger(uint32_t side) { return (side & 1) != 0; }

  private:
    std::vector<size_t> first_; ///< vertex v's half edges are [first_[v], first_[v + 1])
    std::unique_ptr<uint32_t[]> sides_;
};

/// What is wrong with an edge whose sides (from HalfEdgesByCorner) are `sides`; empty when
/// nothing is.
std::string edgeProblem(std::span<const uint32_t> sides) {
    if (sides.size() == 1) return "has one triangle";
    if (sides.size() > 2) return "has " + std::to_string(sides.size()) + " triangles";
    if (sides[0] == sides[1]) return "runs the same way in both of its triangles";
    return {};
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
    HalfEdgesByCorner edges(mesh, welded);
    if (edges.empty()) {
        result.problem = "has no triangles";
        return result;
    }
    for (size_t v = 0; v < edges.vertices(); ++v) {
        const std::span<const uint32_t> sides = edges.sortedAt(v);
        for (size_t i = 0; i < sides.size();) {
            size_t j = i + 1;
            while (j < sides.size() &&
                   HalfEdgesByCorner::larger(sides[j]) == HalfEdgesByCorner::larger(sides[i]))
                ++j;
            std::string problem = edgeProblem(sides.subspan(i, j - i));
            if (!problem.empty()) {
                const auto smaller = static_cast<int32_t>(v),
                           larger = HalfEdgesByCorner::larger(sides[i]);
                const bool fromLarger = HalfEdgesByCorner::runsFromLarger(sides[i]);
                result.edgeFrom = fromLarger ? larger : smaller;
                result.edgeTo = fromLarger ? smaller : larger;
                result.problem = std::move(problem);
                return result;
            }
            i = j;
        }
    }
    double volume = 0;
    forEachWeldedTriangle(mesh, welded, [&](const int32_t(&v)[3]) {
        volume +=
            glm::dot(mesh.positions[v[0]], glm::cross(mesh.positions[v[1]], mesh.positions[v[2]]));
    });
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
