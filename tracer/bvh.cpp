// Binned surface-area-heuristic BVH build (pbrt-v4's BVHAggregate, simplified).
#include "tracer/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace crt::tracer {

namespace {

constexpr int kBins = 12;
constexpr int kMaxLeafItems = 4;
constexpr int kMaxDepth = 56; // below the traversal stack's 64 entries

/// A node of the binary tree the build makes before it is collapsed into the wide one: a
/// leaf holds items[offset .. offset+count); an interior node's first child follows it
/// directly and its second child is nodes[offset].
struct BinaryNode {
    Bounds3 bounds;
    int32_t offset = 0;
    uint16_t count = 0;
};

struct BuildItem {
    Bounds3 bounds;
    Vec3 centroid;
    int32_t index;
};

class Builder {
public:
    Builder(std::vector<BuildItem>& items, std::vector<BinaryNode>& nodes, std::vector<int32_t>& order)
        : items_(items), nodes_(nodes), order_(order) {}

    int build(size_t begin, size_t end, int depth) {
        int32_t nodeIndex = static_cast<int32_t>(nodes_.size());
        nodes_.emplace_back();
        Bounds3 bounds, centroids;
        for (size_t i = begin; i < end; ++i) {
            bounds.include(items_[i].bounds);
            centroids.include(items_[i].centroid);
        }
        nodes_[nodeIndex].bounds = bounds;
        size_t count = end - begin;
        int axis = 0;
        Vec3 extent = centroids.extent();
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;

        bool mustSplit = count > 0xFFFF;
        if ((count <= 1 || extent[axis] <= 0 || depth >= kMaxDepth) && !mustSplit) return makeLeaf(nodeIndex, begin, end, depth);

        size_t mid = begin + count / 2;
        bool median = true;
        if (extent[axis] > 0 && count > 2) {
            int split = bestSplit(begin, end, axis, centroids, bounds, count);
            if (split < 0 && !mustSplit) return makeLeaf(nodeIndex, begin, end, depth);
            if (split >= 0) {
                auto bin = [&](const BuildItem& item) { return binOf(item.centroid[axis], centroids, axis); };
                auto it = std::partition(items_.begin() + begin, items_.begin() + end,
                                         [&](const BuildItem& item) { return bin(item) <= split; });
                mid = static_cast<size_t>(it - items_.begin());
                median = mid == begin || mid == end;
                if (median) mid = begin + count / 2;
            }
        }
        if (median) {
            std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                             [axis](const BuildItem& a, const BuildItem& b) { return a.centroid[axis] < b.centroid[axis]; });
        }
        int leftDepth = build(begin, mid, depth + 1);
        nodes_[nodeIndex].offset = static_cast<int32_t>(nodes_.size());
        int rightDepth = build(mid, end, depth + 1);
        return std::max(leftDepth, rightDepth);
    }

private:
    static int binOf(double c, const Bounds3& centroids, int axis) {
        double f = (c - centroids.lo[axis]) / (centroids.hi[axis] - centroids.lo[axis]);
        return std::clamp(static_cast<int>(f * kBins), 0, kBins - 1);
    }

    /// The bin after which to split, or -1 when a leaf is cheaper.
    int bestSplit(size_t begin, size_t end, int axis, const Bounds3& centroids, const Bounds3& bounds,
                  size_t count) const {
        Bounds3 binBounds[kBins];
        int binCount[kBins] = {};
        for (size_t i = begin; i < end; ++i) {
            int b = binOf(items_[i].centroid[axis], centroids, axis);
            ++binCount[b];
            binBounds[b].include(items_[i].bounds);
        }
        double costs[kBins - 1] = {};
        Bounds3 below;
        int countBelow = 0;
        for (int i = 0; i < kBins - 1; ++i) {
            below.include(binBounds[i]);
            countBelow += binCount[i];
            costs[i] = countBelow * below.surfaceArea();
        }
        Bounds3 above;
        int countAbove = 0;
        for (int i = kBins - 1; i >= 1; --i) {
            above.include(binBounds[i]);
            countAbove += binCount[i];
            costs[i - 1] += countAbove * above.surfaceArea();
        }
        int best = -1;
        double bestCost = kInfinity;
        for (int i = 0; i < kBins - 1; ++i) {
            if (costs[i] < bestCost) {
                bestCost = costs[i];
                best = i;
            }
        }
        double area = bounds.surfaceArea();
        double splitCost = 0.5 + (area > 0 ? bestCost / area : 0);
        if (count <= kMaxLeafItems && splitCost >= static_cast<double>(count)) return -1;
        return best;
    }

    int makeLeaf(int32_t nodeIndex, size_t begin, size_t end, int depth) {
        nodes_[nodeIndex].offset = static_cast<int32_t>(order_.size());
        nodes_[nodeIndex].count = static_cast<uint16_t>(end - begin);
        for (size_t i = begin; i < end; ++i) order_.push_back(items_[i].index);
        return depth;
    }

    std::vector<BuildItem>& items_;
    std::vector<BinaryNode>& nodes_;
    std::vector<int32_t>& order_;
};

float roundDown(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float roundUp(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

/// Turns the binary tree into the 4-wide one: each wide node takes a binary node's two
/// children and keeps opening the interior child of largest surface area until it has four
/// (as Embree's builders do). Returns the wide node's index; `depth` becomes the depth of
/// its subtree.
class Collapser {
public:
    Collapser(const std::vector<BinaryNode>& binary, std::vector<WideBvhNode>& wide) : binary_(binary), wide_(wide) {}

    int32_t collapse(int32_t binaryIndex, int& depth) {
        int32_t wideIndex = static_cast<int32_t>(wide_.size());
        wide_.emplace_back();
        std::vector<int32_t> children;
        const BinaryNode& node = binary_[binaryIndex];
        if (node.count > 0) {
            children.push_back(binaryIndex); // a lone leaf at the root
        } else {
            children = {binaryIndex + 1, node.offset};
            while (children.size() < 4) {
                int widest = -1;
                for (size_t i = 0; i < children.size(); ++i) {
                    const BinaryNode& c = binary_[children[i]];
                    if (c.count == 0 && (widest < 0 || c.bounds.surfaceArea() > binary_[children[widest]].bounds.surfaceArea()))
                        widest = static_cast<int>(i);
                }
                if (widest < 0) break;
                int32_t opened = children[widest];
                children[widest] = opened + 1;
                children.push_back(binary_[opened].offset);
            }
        }
        WideBvhNode filled;
        const float inf = std::numeric_limits<float>::infinity();
        for (int axis = 0; axis < 3; ++axis) {
            filled.faces[axis] = Float4{inf, inf, inf, inf};
            filled.faces[3 + axis] = Float4{-inf, -inf, -inf, -inf};
        }
        filled.used = static_cast<uint32_t>(children.size());
        depth = 1;
        for (size_t slot = 0; slot < 4; ++slot) {
            filled.child[slot] = 0;
            filled.count[slot] = 0;
            if (slot >= children.size()) continue;
            const BinaryNode& c = binary_[children[slot]];
            for (int axis = 0; axis < 3; ++axis) {
                filled.faces[axis][slot] = roundDown(c.bounds.lo[axis]);
                filled.faces[3 + axis][slot] = roundUp(c.bounds.hi[axis]);
            }
            if (c.count > 0) {
                filled.child[slot] = ~c.offset;
                filled.count[slot] = c.count;
            } else {
                int below = 0;
                filled.child[slot] = collapse(children[slot], below);
                depth = std::max(depth, 1 + below);
            }
        }
        wide_[wideIndex] = filled;
        return wideIndex;
    }

private:
    const std::vector<BinaryNode>& binary_;
    std::vector<WideBvhNode>& wide_;
};

} // namespace

WideRay::WideRay(const Ray& ray) {
    for (int axis = 0; axis < 3; ++axis) {
        const double inv = 1.0 / ray.dir[axis];
        const bool negative = inv < 0;
        nearFace[axis] = (negative ? 3 + axis : axis) * sizeof(Float4);
        farFace[axis] = (negative ? axis : 3 + axis) * sizeof(Float4);
        // float(o ± margin) stays on the safe side of o: the margin is at least 4 times the
        // float rounding of a number of o's size.
        const double o = ray.origin[axis];
        const double margin = std::abs(o) * 0x1p-22;
        const double forwards = negative ? -margin : margin;
        const float nearO = static_cast<float>(o + forwards), farO = static_cast<float>(o - forwards);
        const float invF = static_cast<float>(inv), widenedInvF = invF * kWiden;
        nearOrigin[axis] = Float4{nearO, nearO, nearO, nearO};
        farOrigin[axis] = Float4{farO, farO, farO, farO};
        invDir[axis] = Float4{invF, invF, invF, invF};
        widenedInvDir[axis] = Float4{widenedInvF, widenedInvF, widenedInvF, widenedInvF};
    }
}

void Bvh::build(const std::vector<Bounds3>& itemBounds) {
    nodes_.clear();
    items_.clear();
    fewItemBounds_.clear();
    depth_ = 0;
    if (itemBounds.empty()) return;
    std::vector<BuildItem> items(itemBounds.size());
    for (size_t i = 0; i < itemBounds.size(); ++i)
        items[i] = {itemBounds[i], itemBounds[i].centroid(), static_cast<int32_t>(i)};
    std::vector<BinaryNode> binary;
    binary.reserve(2 * items.size());
    items_.reserve(items.size());
    Builder builder(items, binary, items_);
    builder.build(0, items.size(), 0);
    nodes_.reserve(binary.size() / 2 + 1);
    Collapser(binary, nodes_).collapse(0, depth_);
    if (items_.size() <= kFewItems)
        for (int32_t item : items_) {
            const Bounds3& b = itemBounds[item];
            fewItemBounds_.push_back({{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}});
        }
}

} // namespace crt::tracer
