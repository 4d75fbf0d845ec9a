// A bounding volume hierarchy: binned SAH build, flattened depth-first into an array.
#pragma once

#include "tracer/geometry/bounds.hpp"
#include "tracer/stats.hpp"

#include <cstdint>
#include <vector>

namespace crt::tracer {

/// A node: a leaf holds items[offset .. offset+count); an interior node's first child
/// follows it directly and its second child is nodes[offset].
struct BvhNode {
    Bounds3 bounds;
    int32_t offset = 0;
    uint16_t count = 0;
    uint8_t axis = 0;
};

/// A ray prepared for box tests.
struct BoxRay {
    Vec3 origin;
    Vec3 invDir;
    int dirIsNegative[3];

    explicit BoxRay(const Ray& ray)
        : origin(ray.origin), invDir(1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z),
          dirIsNegative{invDir.x < 0, invDir.y < 0, invDir.z < 0} {}

    /// Whether the segment (tMin, tMax) of the ray meets the box (pbrt's slab test, with the
    /// far distance widened by the rounding bound so a grazing hit is never culled).
    bool hits(const Bounds3& b, double tMin, double tMax) const {
        const Vec3* corners[2] = {&b.lo, &b.hi};
        double t0 = (corners[dirIsNegative[0]]->x - origin.x) * invDir.x;
        double t1 = (corners[1 - dirIsNegative[0]]->x - origin.x) * invDir.x;
        double ty0 = (corners[dirIsNegative[1]]->y - origin.y) * invDir.y;
        double ty1 = (corners[1 - dirIsNegative[1]]->y - origin.y) * invDir.y;
        constexpr double widen = 1 + 2 * errorGamma(3);
        t1 *= widen;
        ty1 *= widen;
        if (t0 > ty1 || ty0 > t1) return false;
        if (ty0 > t0) t0 = ty0;
        if (ty1 < t1) t1 = ty1;
        double tz0 = (corners[dirIsNegative[2]]->z - origin.z) * invDir.z;
        double tz1 = (corners[1 - dirIsNegative[2]]->z - origin.z) * invDir.z * widen;
        if (t0 > tz1 || tz0 > t1) return false;
        if (tz0 > t0) t0 = tz0;
        if (tz1 < t1) t1 = tz1;
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
        int32_t stack[64];
        int top = 0;
        int32_t current = 0;
        while (true) {
            const BvhNode& node = nodes_[current];
            ++stats.nodesVisited;
            if (boxRay.hits(node.bounds, 0.0, tMax)) {
                if (node.count > 0) {
                    for (int i = 0; i < node.count; ++i)
                        if (!visit(items_[node.offset + i])) return false;
                    if (top == 0) break;
                    current = stack[--top];
                } else if (boxRay.dirIsNegative[node.axis]) {
                    stack[top++] = current + 1;
                    current = node.offset;
                } else {
                    stack[top++] = node.offset;
                    current = current + 1;
                }
            } else {
                if (top == 0) break;
                current = stack[--top];
            }
        }
        return true;
    }

private:
    std::vector<BvhNode> nodes_;
    std::vector<int32_t> items_;
    int depth_ = 0;
};

} // namespace crt::tracer
