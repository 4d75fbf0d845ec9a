// A bounding volume hierarchy: binned SAH build, flattened depth-first into an array.
#pragma once

#include "tracer/geometry/bounds.hpp"
#include "tracer/stats.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace crt::tracer {

/// A node: a leaf holds items[offset .. offset+count); an interior node's first child
/// follows it directly and its second child is nodes[offset].
struct BvhNode {
    double faces[6]; ///< the box: lo.x, lo.y, lo.z, hi.x, hi.y, hi.z (indexed by BoxRay)
    int32_t offset = 0;
    uint16_t count = 0;
    uint8_t axis = 0;
};

/// A ray prepared for box tests: the reciprocal direction, and for each axis which face of a
/// box the ray meets first, so the slab test needs no branch on the direction.
struct BoxRay {
    Vec3 origin;
    Vec3 invDir;
    int dirIsNegative[3];
    int nearFace[3]; ///< index into Bounds3 viewed as {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}
    int farFace[3];

    explicit BoxRay(const Ray& ray)
        : origin(ray.origin), invDir(1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z),
          dirIsNegative{invDir.x < 0, invDir.y < 0, invDir.z < 0} {
        for (int i = 0; i < 3; ++i) {
            nearFace[i] = dirIsNegative[i] ? 3 + i : i;
            farFace[i] = dirIsNegative[i] ? i : 3 + i;
        }
    }

    /// Whether the segment (tMin, tMax) of the ray meets the box (pbrt's slab test, with the
    /// far distance widened by the rounding bound so a grazing hit is never culled).
    bool hits(const Bounds3& b, double tMin, double tMax) const {
        const double faces[6] = {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
        return hits(faces, tMin, tMax);
    }
    bool hits(const double* faces, double tMin, double tMax) const {
        double entry;
        return hits(faces, tMin, tMax, entry);
    }
    /// The same, also giving where the ray enters the box (for nearest-first traversal).
    bool hits(const double* faces, double tMin, double tMax, double& entry) const {
        constexpr double widen = 1 + 2 * errorGamma(3);
        double t0 = (faces[nearFace[0]] - origin.x) * invDir.x;
        double t1 = (faces[farFace[0]] - origin.x) * invDir.x * widen;
        double ty0 = (faces[nearFace[1]] - origin.y) * invDir.y;
        double ty1 = (faces[farFace[1]] - origin.y) * invDir.y * widen;
        if (t0 > ty1 || ty0 > t1) return false;
        if (ty0 > t0) t0 = ty0;
        if (ty1 < t1) t1 = ty1;
        double tz0 = (faces[nearFace[2]] - origin.z) * invDir.z;
        double tz1 = (faces[farFace[2]] - origin.z) * invDir.z * widen;
        if (t0 > tz1 || tz0 > t1) return false;
        if (tz0 > t0) t0 = tz0;
        if (tz1 < t1) t1 = tz1;
        entry = t0;
        return t0 < tMax && t1 > tMin;
    }
};

class Bvh {
public:
    /// Builds over items 0..n-1 with the given (finite) bounds.
    void build(const std::vector<Bounds3>& itemBounds);

    bool empty() const { return nodes_.empty(); }
    size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }

    /// Visits the items whose leaves the ray segment (0, tMax) reaches, nearer subtrees
    /// first; `tMax` may shrink while visiting (a nearest-hit search). visit(item) returns
    /// false to stop; traverse then returns false.
    template <typename Visit>
    bool traverse(const Ray& ray, const double& tMax, RayStats& stats, Visit&& visit) const {
        if (nodes_.empty()) return true;
        BoxRay boxRay(ray);
        uint64_t visited = 1; // counted locally: the stats live in memory
        if (!boxRay.hits(nodes_[0].faces, 0.0, tMax)) {
            stats.nodesVisited += visited;
            return true;
        }
        // Children are tested from their parent; the nearer one (by entry distance) is
        // visited first and the farther one waits on the stack, rechecked against the
        // then-current tMax when popped.
        struct Pending {
            int32_t node;
            double entry;
        };
        Pending stack[64];
        int top = 0;
        int32_t current = 0;
        while (true) {
            const BvhNode& node = nodes_[current];
            if (node.count > 0) {
                for (int i = 0; i < node.count; ++i) {
                    if (!visit(items_[node.offset + i])) {
                        stats.nodesVisited += visited;
                        return false;
                    }
                }
            } else {
                int32_t first = current + 1, second = node.offset;
                double firstEntry = 0, secondEntry = 0;
                visited += 2;
                bool hitFirst = boxRay.hits(nodes_[first].faces, 0.0, tMax, firstEntry);
                bool hitSecond = boxRay.hits(nodes_[second].faces, 0.0, tMax, secondEntry);
                if (hitFirst && hitSecond) {
                    if (secondEntry < firstEntry) {
                        std::swap(first, second);
                        std::swap(firstEntry, secondEntry);
                    }
                    stack[top++] = {second, secondEntry};
                    current = first;
                    continue;
                }
                if (hitFirst || hitSecond) {
                    current = hitFirst ? first : second;
                    continue;
                }
            }
            // Next: the nearest pending subtree still in front of the nearest hit so far.
            do {
                if (top == 0) {
                    stats.nodesVisited += visited;
                    return true;
                }
                --top;
            } while (stack[top].entry >= tMax);
            current = stack[top].node;
        }
    }

private:
    std::vector<BvhNode> nodes_;
    std::vector<int32_t> items_;
    int depth_ = 0;
};

} // namespace crt::tracer
