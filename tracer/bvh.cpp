// Binned surface-area-heuristic BVH build (pbrt-v4's BVHAggregate, simplified).
#include "tracer/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <system_error>

namespace crt::tracer {

namespace {

constexpr int kBins = 12;
constexpr int kMaxLeafItems = 4;
constexpr int kMaxDepth = 56; // below the traversal stack's 64 entries
// Subtrees of fewer items are built by the thread that reaches them: they take a
// millisecond or less, not worth a thread of their own.
constexpr size_t kParallelItems = 8192;

/// Frees a vector's memory (assigning {} keeps it: that assigns an empty initializer list).
template <typename T> void release(std::vector<T>& v) { std::vector<T>().swap(v); }

float roundDown(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float roundUp(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

/// A box in single precision, its faces rounded outwards from the bounds it stands for: as
/// the wide tree stores boxes, and in half the bytes of a Bounds3, so that the build's items
/// and nodes take 32 bytes each.
struct FloatBox {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};

    static FloatBox outward(const Bounds3& b) {
        FloatBox f;
        for (int axis = 0; axis < 3; ++axis) {
            f.lo[axis] = roundDown(b.lo[axis]);
            f.hi[axis] = roundUp(b.hi[axis]);
        }
        return f;
    }
    void include(const FloatBox& o) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = std::min(lo[axis], o.lo[axis]);
            hi[axis] = std::max(hi[axis], o.hi[axis]);
        }
    }
    // Measured on the faces clamped to the finite floats, so that a box reaching past them
    // (its faces rounded to infinity) still has a centroid and an area to compare.
    double clampedLo(int axis) const { return std::max(lo[axis], -std::numeric_limits<float>::max()); }
    double clampedHi(int axis) const { return std::min(hi[axis], std::numeric_limits<float>::max()); }
    double centroid(int axis) const { return 0.5 * (clampedLo(axis) + clampedHi(axis)); }
    double surfaceArea() const {
        double e[3];
        for (int axis = 0; axis < 3; ++axis) e[axis] = std::max(clampedHi(axis) - clampedLo(axis), 0.0);
        return 2 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
    }
};

/// A node of the binary tree the build makes before it is collapsed into the wide one: a
/// leaf holds items[offset .. offset+count); an interior node's first child follows it
/// directly and its second child is nodes[offset].
struct BinaryNode {
    FloatBox bounds;
    int32_t offset = 0;
    uint16_t count = 0;
};

struct BuildItem {
    FloatBox bounds;
    int32_t index; ///< the item's position in the build's input
    uint8_t bin;   ///< set by bestSplit for the node being split (in what was padding)

    double centroid(int axis) const { return bounds.centroid(axis); }
};

/// The bounds of some items and of their centroids (which choose the split axis and bins).
struct RangeBounds {
    FloatBox bounds;
    Bounds3 centroids;

    void include(const BuildItem& item) {
        bounds.include(item.bounds);
        centroids.include(Vec3(item.centroid(0), item.centroid(1), item.centroid(2)));
    }
};

/// Builds the binary tree over `items` (reordering them), depth-first: a node, its first
/// subtree, its second. Near the root the two subtrees are built by two threads into builders
/// of their own and then appended in that order, so the tree is the same whatever the
/// number of threads.
class Builder {
public:
    /// A builder for a subtree of `count` items: a binary tree with leaves of one item or
    /// more has fewer than 2 · count nodes.
    Builder(std::vector<BuildItem>& items, size_t count) : items_(items) {
        nodes.reserve(2 * count);
        order.reserve(count);
    }

    std::vector<BinaryNode> nodes;
    std::vector<int32_t> order; ///< item indices in the order of the leaves

    /// Builds the subtree over items [begin, end); below `parallelLevels` levels from here,
    /// one thread. Returns the depth of its deepest leaf.
    int build(size_t begin, size_t end, int depth, int parallelLevels) {
        int32_t nodeIndex = static_cast<int32_t>(nodes.size());
        nodes.emplace_back();
        const RangeBounds range = boundsOf(begin, end);
        nodes[nodeIndex].bounds = range.bounds;
        size_t count = end - begin;
        int axis = 0;
        Vec3 extent = range.centroids.extent();
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;

        bool mustSplit = count > 0xFFFF;
        if ((count <= 1 || extent[axis] <= 0 || depth >= kMaxDepth) && !mustSplit) return makeLeaf(nodeIndex, begin, end, depth);

        size_t mid = begin + count / 2;
        bool median = true;
        if (extent[axis] > 0 && count > 2) {
            int split = bestSplit(begin, end, axis, range, count);
            if (split < 0 && !mustSplit) return makeLeaf(nodeIndex, begin, end, depth);
            if (split >= 0) {
                auto it = std::partition(items_.begin() + begin, items_.begin() + end,
                                         [&](const BuildItem& item) { return item.bin <= split; });
                mid = static_cast<size_t>(it - items_.begin());
                median = mid == begin || mid == end;
                if (median) mid = begin + count / 2;
            }
        }
        if (median) {
            std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                             [axis](const BuildItem& a, const BuildItem& b) { return a.centroid(axis) < b.centroid(axis); });
        }
        if (parallelLevels > 0 && count >= kParallelItems)
            return buildChildrenInParallel(nodeIndex, begin, mid, end, depth, parallelLevels - 1);
        int leftDepth = build(begin, mid, depth + 1, 0);
        nodes[nodeIndex].offset = static_cast<int32_t>(nodes.size());
        int rightDepth = build(mid, end, depth + 1, 0);
        return std::max(leftDepth, rightDepth);
    }

private:
    /// The children of nodes[nodeIndex], over items [begin, mid) and [mid, end): the first
    /// built on a thread of its own (or later on this one, when no thread can be had).
    int buildChildrenInParallel(int32_t nodeIndex, size_t begin, size_t mid, size_t end, int depth,
                                int parallelLevels) {
        Builder left(items_, mid - begin), right(items_, end - mid);
        auto buildLeft = [&] { return left.build(begin, mid, depth + 1, parallelLevels); };
        std::future<int> leftDepth;
        try {
            leftDepth = std::async(std::launch::async, buildLeft);
        } catch (const std::system_error&) {
            leftDepth = std::async(std::launch::deferred, buildLeft);
        }
        const int rightDepth = right.build(mid, end, depth + 1, parallelLevels);
        const int depthReached = std::max(leftDepth.get(), rightDepth);
        append(std::move(left));
        nodes[nodeIndex].offset = static_cast<int32_t>(nodes.size());
        append(std::move(right));
        return depthReached;
    }

    /// Appends a subtree built apart, its node and item offsets moved past ours, and frees
    /// it (so that at most one subtree is held twice).
    void append(Builder&& subtree) {
        const auto nodeBase = static_cast<int32_t>(nodes.size());
        const auto orderBase = static_cast<int32_t>(order.size());
        for (BinaryNode node : subtree.nodes) {
            node.offset += node.count > 0 ? orderBase : nodeBase;
            nodes.push_back(node);
        }
        order.insert(order.end(), subtree.order.begin(), subtree.order.end());
        release(subtree.nodes);
        release(subtree.order);
    }

    static int binOf(double c, const Bounds3& centroids, int axis) {
        double f = (c - centroids.lo[axis]) / (centroids.hi[axis] - centroids.lo[axis]);
        return std::clamp(static_cast<int>(f * kBins), 0, kBins - 1);
    }

    RangeBounds boundsOf(size_t begin, size_t end) const {
        RangeBounds range;
        for (size_t i = begin; i < end; ++i) range.include(items_[i]);
        return range;
    }

    /// The bin after which to split, or -1 when a leaf is cheaper; leaves each item's bin in
    /// it, for the partition that follows.
    int bestSplit(size_t begin, size_t end, int axis, const RangeBounds& range, size_t count) {
        FloatBox bins[kBins];
        int binCount[kBins] = {};
        for (size_t i = begin; i < end; ++i) {
            int b = binOf(items_[i].centroid(axis), range.centroids, axis);
            items_[i].bin = static_cast<uint8_t>(b);
            ++binCount[b];
            bins[b].include(items_[i].bounds);
        }
        double costs[kBins - 1] = {};
        FloatBox below;
        int countBelow = 0;
        for (int i = 0; i < kBins - 1; ++i) {
            below.include(bins[i]);
            countBelow += binCount[i];
            costs[i] = countBelow * below.surfaceArea();
        }
        FloatBox above;
        int countAbove = 0;
        for (int i = kBins - 1; i >= 1; --i) {
            above.include(bins[i]);
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
        double area = range.bounds.surfaceArea();
        double splitCost = 0.5 + (area > 0 ? bestCost / area : 0);
        if (count <= kMaxLeafItems && splitCost >= static_cast<double>(count)) return -1;
        return best;
    }

    int makeLeaf(int32_t nodeIndex, size_t begin, size_t end, int depth) {
        nodes[nodeIndex].offset = static_cast<int32_t>(order.size());
        nodes[nodeIndex].count = static_cast<uint16_t>(end - begin);
        for (size_t i = begin; i < end; ++i) order.push_back(items_[i].index);
        return depth;
    }

    std::vector<BuildItem>& items_;
};

/// Turns the binary tree into the 4-wide one: each wide node takes a binary node's two
/// children and keeps opening the interior child of largest surface area until it has four
/// (as Embree's builders do). Returns the wide node's index; `depth` becomes the depth of
/// its subtree.
class Collapser {
public:
    Collapser(const std::vector<BinaryNode>& binary, std::vector<WideBvhNode>& wide) : binary_(binary), wide_(wide) {}

    /// The wide nodes the subtree at binaryIndex collapses to (so that they can be stored in
    /// one allocation of the right size).
    size_t count(int32_t binaryIndex) const {
        int32_t children[4];
        const size_t childCount = gather(binaryIndex, children);
        size_t total = 1;
        for (size_t slot = 0; slot < childCount; ++slot)
            if (binary_[children[slot]].count == 0) total += count(children[slot]);
        return total;
    }

    int32_t collapse(int32_t binaryIndex, int& depth) {
        int32_t wideIndex = static_cast<int32_t>(wide_.size());
        wide_.emplace_back();
        int32_t children[4];
        const size_t childCount = gather(binaryIndex, children);
        WideBvhNode filled;
        const float inf = std::numeric_limits<float>::infinity();
        for (int axis = 0; axis < 3; ++axis) {
            filled.faces[axis] = Float4{inf, inf, inf, inf};
            filled.faces[3 + axis] = Float4{-inf, -inf, -inf, -inf};
        }
        filled.used = static_cast<uint32_t>(childCount);
        depth = 1;
        for (size_t slot = 0; slot < 4; ++slot) {
            filled.child[slot] = 0;
            filled.count[slot] = 0;
            if (slot >= childCount) continue;
            const BinaryNode& c = binary_[children[slot]];
            for (int axis = 0; axis < 3; ++axis) {
                filled.faces[axis][slot] = c.bounds.lo[axis];
                filled.faces[3 + axis][slot] = c.bounds.hi[axis];
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
    /// The binary nodes that become the wide node's children: the binary node's two, then
    /// the interior child of largest surface area opened until there are four.
    size_t gather(int32_t binaryIndex, int32_t (&children)[4]) const {
        size_t childCount = 0;
        const BinaryNode& node = binary_[binaryIndex];
        if (node.count > 0) {
            children[childCount++] = binaryIndex; // a lone leaf at the root
            return childCount;
        }
        children[childCount++] = binaryIndex + 1;
        children[childCount++] = node.offset;
        while (childCount < 4) {
            int widest = -1;
            for (size_t i = 0; i < childCount; ++i) {
                const BinaryNode& c = binary_[children[i]];
                if (c.count == 0 && (widest < 0 || c.bounds.surfaceArea() > binary_[children[widest]].bounds.surfaceArea()))
                    widest = static_cast<int>(i);
            }
            if (widest < 0) break;
            int32_t opened = children[widest];
            children[widest] = opened + 1;
            children[childCount++] = binary_[opened].offset;
        }
        return childCount;
    }

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

void Bvh::buildFrom(size_t count, ItemBounds boundsOf, unsigned threads, std::vector<int32_t> ids) {
    nodes_.clear();
    items_.clear();
    fewItemBounds_.clear();
    depth_ = 0;
    if (count == 0) return;
    std::vector<BuildItem> items(count);
    for (size_t i = 0; i < count; ++i) items[i] = {FloatBox::outward(boundsOf(i)), static_cast<int32_t>(i), 0};
    // Levels of the tree whose two subtrees are built by two threads: twice as many subtrees
    // as threads, so that an uneven split still leaves every thread busy.
    int parallelLevels = 0;
    while (threads > 1 && (1u << parallelLevels) < 2 * threads) ++parallelLevels;
    Builder builder(items, items.size());
    builder.build(0, items.size(), 0, parallelLevels);
    release(items); // not held while the wide tree is made beside the binary one
    // The build leaves the input positions in the order of the leaves.
    items_ = std::move(builder.order);
    for (int32_t& item : items_) {
        if (count <= kFewItems) { // these keep their exact boxes
            const Bounds3 b = boundsOf(static_cast<size_t>(item));
            fewItemBounds_.push_back({{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}});
        }
        if (!ids.empty()) item = ids[static_cast<size_t>(item)];
    }
    Collapser collapser(builder.nodes, nodes_);
    nodes_.reserve(collapser.count(0));
    collapser.collapse(0, depth_);
}

} // namespace crt::tracer
