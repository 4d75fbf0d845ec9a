// Binned surface-area-heuristic BVH build (pbrt-v4's BVHAggregate, simplified).
#include "tracer/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <future>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
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

/// The float next to f towards -infinity or +infinity (as std::nextafter, without a call into
/// the maths library for each face of each item).
float nextDown(float f) {
    if (f == 0) return -std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<int32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}
float nextUp(float f) { return -nextDown(-f); }

float roundDown(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? nextDown(f) : f;
}

float roundUp(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? nextUp(f) : f;
}

/// A box in single precision held in four lanes (x, y, z, and one it does not use), so that
/// growing it is one vector min and one vector max.
struct Box4 {
    static constexpr float inf = std::numeric_limits<float>::infinity();
    Float4 lo = {inf, inf, inf, inf};
    Float4 hi = {-inf, -inf, -inf, -inf};

    void include(Float4 l, Float4 h) {
        lo = l < lo ? l : lo;
        hi = h > hi ? h : hi;
    }
    void include(const Box4& o) { include(o.lo, o.hi); }
    double extent(int axis) const { return double(hi[axis]) - lo[axis]; }
    // Measured on the faces clamped to the finite floats, so that a box reaching past them
    // (its faces rounded to infinity) still has an area to compare.
    double surfaceArea() const {
        double e[3];
        for (int axis = 0; axis < 3; ++axis)
            e[axis] = std::max(std::min(double(hi[axis]), kFloatMax) - std::max(double(lo[axis]), -kFloatMax), 0.0);
        return 2 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
    }

    static constexpr double kFloatMax = std::numeric_limits<float>::max();
};

/// A node of the binary tree the build makes before it is collapsed into the wide one: a
/// leaf holds items[offset .. offset+count); an interior node's first child follows it
/// directly and its second child is nodes[offset]. Its box is kept in 24 bytes, not a
/// Box4's 32, as a large build holds twice as many nodes as items.
struct BinaryNode {
    float lo[3], hi[3];
    int32_t offset;
    uint16_t count;

    void setBounds(const Box4& box) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = box.lo[axis];
            hi[axis] = box.hi[axis];
        }
    }
    double surfaceArea() const {
        Box4 box;
        box.lo = Float4{lo[0], lo[1], lo[2], 0};
        box.hi = Float4{hi[0], hi[1], hi[2], 0};
        return box.surfaceArea();
    }
};

/// An item of the build: its bounds rounded outwards to float. The faces and the two
/// integers are laid out so that each group of four is one Float4 load, the integer's lane
/// ignored: an item takes 32 bytes.
struct alignas(16) BuildItem {
    float lo[3];
    int32_t index; ///< the item's position in the build's input
    float hi[3];
    uint32_t bin; ///< set by bestSplit for the node being split

    BuildItem(const Bounds3& b, int32_t i) : index(i), bin(0) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = roundDown(b.lo[axis]);
            hi[axis] = roundUp(b.hi[axis]);
        }
    }
    BuildItem() = default;

    Float4 loLanes() const { return lanes(0); }
    Float4 hiLanes() const { return lanes(sizeof(Float4)); }
    /// The centre of the box clamped to the finite floats (so that one reaching past them
    /// still has a centre), in lanes 0-2; lane 3 is 0.
    Float4 centroid() const { return centroidOf(loLanes(), hiLanes()); }
    static Float4 centroidOf(Float4 l, Float4 h) {
        constexpr float big = std::numeric_limits<float>::max();
        const Float4 clampedLo = l > -big ? l : Float4{-big, -big, -big, -big};
        const Float4 clampedHi = h < big ? h : Float4{big, big, big, big};
        // Halves added, not the sum halved, so that two faces near the largest float do not
        // overflow.
        return 0.5f * clampedLo + 0.5f * clampedHi;
    }

private:
    /// The three faces at byte `offset` in lanes 0-2, loaded as one (a narrower copy would
    /// stall the load that follows it), and 0 in lane 3 rather than the integer's bits, which
    /// read as a float may be a denormal that slows arithmetic down.
    Float4 lanes(size_t offset) const {
        Float4 v;
        std::memcpy(&v, reinterpret_cast<const char*>(this) + offset, sizeof v);
        return reinterpret_cast<Float4>(reinterpret_cast<Int4>(v) & Int4{-1, -1, -1, 0});
    }
};
static_assert(sizeof(BuildItem) == 2 * sizeof(Float4) && offsetof(BuildItem, hi) == sizeof(Float4));

/// The bounds of some items and of their centroids (which choose the split axis and bins).
struct RangeBounds {
    Box4 bounds;
    Box4 centroids;

    void include(const BuildItem& item) {
        bounds.include(item.loLanes(), item.hiLanes());
        const Float4 c = item.centroid();
        centroids.include(c, c);
    }
    void include(const RangeBounds& other) {
        bounds.include(other.bounds);
        centroids.include(other.centroids);
    }
};

/// Builds the binary tree over `items` (reordering them), depth-first: a node, its first
/// subtree, its second. A subtree over n items takes at most 2n - 1 nodes, so each has its
/// place in `nodes` fixed by its items alone: near the root the two subtrees are built by
/// two threads straight into their places, and the tree is the same whatever the number of
/// threads. A leaf's items are where the build leaves them in `items`.
class Builder {
public:
    explicit Builder(std::vector<BuildItem>& items)
        : nodes(std::make_unique_for_overwrite<BinaryNode[]>(2 * items.size() - 1)), items_(items) {}

    /// Not initialised: each node is written by the thread that builds it, and the places
    /// between subtrees that no node refers to are never touched.
    std::unique_ptr<BinaryNode[]> nodes;

    /// Where to split a node's items, and the bounds of the two sides.
    struct Split {
        size_t mid; ///< the first item of the second side
        RangeBounds below, above;
    };

    /// Builds the subtree over items [begin, end), whose bounds are `range`, at nodes[node]
    /// onwards; below `parallelLevels` levels from here, one thread. Returns the depth of its
    /// deepest leaf.
    int build(size_t begin, size_t end, size_t node, const RangeBounds& range, int depth, int parallelLevels) {
        nodes[node].setBounds(range.bounds);
        size_t count = end - begin;
        int axis = 0;
        if (range.centroids.extent(1) > range.centroids.extent(axis)) axis = 1;
        if (range.centroids.extent(2) > range.centroids.extent(axis)) axis = 2;
        const bool spread = range.centroids.extent(axis) > 0;

        bool mustSplit = count > 0xFFFF;
        if ((count <= 1 || !spread || depth >= kMaxDepth) && !mustSplit) return makeLeaf(node, begin, end, depth);

        std::optional<Split> split = chooseSplit(begin, end, axis, range);
        if (!split) {
            if (!mustSplit) return makeLeaf(node, begin, end, depth);
            split = medianSplit(begin, end, axis);
        }
        // The first subtree follows its parent; the second comes after the most the first
        // can take.
        const size_t second = node + 2 * (split->mid - begin);
        nodes[node].offset = static_cast<int32_t>(second);
        nodes[node].count = 0;
        const int levelsBelow = std::max(parallelLevels - 1, 0);
        auto buildFirst = [&, split] { return build(begin, split->mid, node + 1, split->below, depth + 1, levelsBelow); };
        std::future<int> firstDepth;
        if (parallelLevels > 0 && count >= kParallelItems) {
            try {
                firstDepth = std::async(std::launch::async, buildFirst);
            } catch (const std::system_error&) {
                // no thread to be had: built below, on this one
            }
        }
        const int secondDepth = build(split->mid, end, second, split->above, depth + 1, levelsBelow);
        return std::max(firstDepth.valid() ? firstDepth.get() : buildFirst(), secondDepth);
    }

    RangeBounds boundsOf(size_t begin, size_t end) const {
        RangeBounds range;
        for (size_t i = begin; i < end; ++i) range.include(items_[i]);
        return range;
    }

private:
    /// The split the surface area heuristic prefers, or none when a leaf is cheaper (the cost
    /// of a leaf is its items; of a split, half an item plus each side's items weighted by
    /// the share of the node's area its bounds take). Falls back on the median where the
    /// heuristic's split leaves a side empty.
    std::optional<Split> chooseSplit(size_t begin, size_t end, int axis, const RangeBounds& range) {
        const size_t count = end - begin;
        if (range.centroids.extent(axis) <= 0) return std::nullopt;
        if (count <= static_cast<size_t>(kBins)) return sortedSplit(begin, end, axis, range);
        std::optional<Split> split = binnedSplit(begin, end, axis, range);
        if (split && (split->mid == begin || split->mid == end)) return medianSplit(begin, end, axis);
        return split;
    }

    /// Whether a split of this cost (the sum over its sides of items times area) beats a leaf.
    static bool splitPays(double cost, const RangeBounds& range, size_t count) {
        const double area = range.bounds.surfaceArea();
        return count > kMaxLeafItems || 0.5 + (area > 0 ? cost / area : 0) < static_cast<double>(count);
    }

    /// Halves at the median centroid along `axis`.
    Split medianSplit(size_t begin, size_t end, int axis) {
        const size_t mid = begin + (end - begin) / 2;
        std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                         [axis](const BuildItem& a, const BuildItem& b) { return a.centroid()[axis] < b.centroid()[axis]; });
        return {mid, boundsOf(begin, mid), boundsOf(mid, end)};
    }

    /// A few items: sorted along the axis, every split between two of them is weighed (bins
    /// would be mostly empty, and setting them up costs more than the items).
    std::optional<Split> sortedSplit(size_t begin, size_t end, int axis, const RangeBounds& range) {
        const size_t count = end - begin;
        // Sorted by insertion on keys computed once, not by a comparison computing two
        // centroids each time.
        struct Keyed {
            float key;
            BuildItem item;
        };
        Keyed sorted[kBins];
        for (size_t i = 0; i < count; ++i) {
            Keyed k{items_[begin + i].centroid()[axis], items_[begin + i]};
            size_t at = i;
            for (; at > 0 && sorted[at - 1].key > k.key; --at) sorted[at] = sorted[at - 1];
            sorted[at] = k;
        }
        for (size_t i = 0; i < count; ++i) items_[begin + i] = sorted[i].item;
        // The area of the items from i on, then the cost of splitting before each i.
        double aboveArea[kBins];
        Box4 above;
        for (size_t i = count - 1; i >= 1; --i) {
            above.include(sorted[i].item.loLanes(), sorted[i].item.hiLanes());
            aboveArea[i] = above.surfaceArea();
        }
        Box4 below;
        size_t best = 0;
        double bestCost = kInfinity;
        for (size_t i = 1; i < count; ++i) {
            below.include(sorted[i - 1].item.loLanes(), sorted[i - 1].item.hiLanes());
            const double cost = double(i) * below.surfaceArea() + double(count - i) * aboveArea[i];
            if (cost < bestCost) {
                bestCost = cost;
                best = i;
            }
        }
        if (!splitPays(bestCost, range, count)) return std::nullopt;
        const size_t mid = begin + best;
        return Split{mid, boundsOf(begin, mid), boundsOf(mid, end)};
    }

    /// Many items: binned by centroid along the axis, the splits between bins weighed.
    std::optional<Split> binnedSplit(size_t begin, size_t end, int axis, const RangeBounds& range) {
        const size_t count = end - begin;
        // Neighbouring items mostly fall into the same bin, and growing a bin waits for its
        // last update: two sets of bins, for the even and the odd items, halve that wait.
        RangeBounds lanes[2][kBins];
        int laneCount[2][kBins] = {};
        const double lo = range.centroids.lo[axis];
        const double scale = kBins / range.centroids.extent(axis);
        for (size_t i = begin; i < end; ++i) {
            BuildItem& item = items_[i];
            // Both halves read before the bin is written into the second: a read overlapping
            // a write just made waits for it.
            const Float4 l = item.loLanes(), h = item.hiLanes();
            const Float4 centroid = BuildItem::centroidOf(l, h);
            const int b = std::clamp(static_cast<int>((centroid[axis] - lo) * scale), 0, kBins - 1);
            const size_t lane = i & 1;
            ++laneCount[lane][b];
            lanes[lane][b].bounds.include(l, h);
            lanes[lane][b].centroids.include(centroid, centroid);
            item.bin = static_cast<uint32_t>(b);
        }
        RangeBounds bins[kBins];
        int binCount[kBins];
        for (int b = 0; b < kBins; ++b) {
            bins[b] = lanes[0][b];
            bins[b].include(lanes[1][b]);
            binCount[b] = laneCount[0][b] + laneCount[1][b];
        }
        // The cost of each split: the items on each side times the area of their bounds.
        double costs[kBins - 1] = {};
        Box4 below;
        int countBelow = 0;
        for (int i = 0; i < kBins - 1; ++i) {
            below.include(bins[i].bounds);
            countBelow += binCount[i];
            costs[i] = countBelow * below.surfaceArea();
        }
        Box4 above;
        int countAbove = 0;
        for (int i = kBins - 1; i >= 1; --i) {
            above.include(bins[i].bounds);
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
        if (!splitPays(bestCost, range, count)) return std::nullopt;
        Split split{begin, {}, {}};
        for (int i = 0; i < kBins; ++i) (i <= best ? split.below : split.above).include(bins[i]);
        auto second = std::partition(items_.begin() + begin, items_.begin() + end,
                                     [&](const BuildItem& item) { return static_cast<int>(item.bin) <= best; });
        split.mid = static_cast<size_t>(second - items_.begin());
        return split;
    }

    int makeLeaf(size_t node, size_t begin, size_t end, int depth) {
        nodes[node].offset = static_cast<int32_t>(begin);
        nodes[node].count = static_cast<uint16_t>(end - begin);
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
    /// `order`: the items in the order of the binary leaves, as positions in the build's input;
    /// `ids`: what each position stands for (empty: the position itself). The wide tree goes
    /// to `wide`, the items of its leaves of more than one to `items`.
    Collapser(const BinaryNode* binary, const std::vector<int32_t>& order,
              const std::vector<int32_t>& ids, std::vector<WideBvhNode>& wide, std::vector<int32_t>& items)
        : binary_(binary), order_(order), ids_(ids), wide_(wide), items_(items) {}

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
        depth = 1;
        for (size_t slot = 0; slot < 4; ++slot) {
            filled.child[slot] = WideChild::node(0);
            if (slot >= childCount) continue;
            const BinaryNode& c = binary_[children[slot]];
            for (int axis = 0; axis < 3; ++axis) {
                filled.faces[axis][slot] = c.lo[axis];
                filled.faces[3 + axis][slot] = c.hi[axis];
            }
            if (c.count > 0) {
                filled.child[slot] = leafChild(c);
            } else {
                int below = 0;
                filled.child[slot] = WideChild::node(static_cast<uint32_t>(collapse(children[slot], below)));
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
                if (c.count == 0 && (widest < 0 || c.surfaceArea() > binary_[children[widest]].surfaceArea()))
                    widest = static_cast<int>(i);
            }
            if (widest < 0) break;
            int32_t opened = children[widest];
            children[widest] = opened + 1;
            children[childCount++] = binary_[opened].offset;
        }
        return childCount;
    }

    /// A leaf's `child` in the wide tree: its item, or where its items start in items_.
    uint32_t leafChild(const BinaryNode& leaf) {
        auto id = [&](size_t k) {
            const int32_t position = order_[static_cast<size_t>(leaf.offset) + k];
            return ids_.empty() ? position : ids_[static_cast<size_t>(position)];
        };
        if (leaf.count == 1) return WideChild::item(static_cast<uint32_t>(id(0)));
        const auto start = static_cast<uint32_t>(items_.size());
        items_.push_back(leaf.count);
        for (size_t k = 0; k < leaf.count; ++k) items_.push_back(id(k));
        return WideChild::items(start);
    }

    const BinaryNode* binary_;
    const std::vector<int32_t>& order_;
    const std::vector<int32_t>& ids_;
    std::vector<WideBvhNode>& wide_;
    std::vector<int32_t>& items_;
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
    fewItems_.clear();
    depth_ = 0;
    if (count == 0) return;
    const bool numberable = count < WideChild::kMaxItems / 2 &&
                            std::all_of(ids.begin(), ids.end(), [](int32_t id) {
                                return id >= 0 && static_cast<uint32_t>(id) < WideChild::kMaxItems;
                            });
    if (!numberable) throw std::length_error("BVH items must be numbers below 2^30, fewer than 2^29");
    std::vector<BuildItem> items;
    items.reserve(count);
    for (size_t i = 0; i < count; ++i) items.emplace_back(boundsOf(i), static_cast<int32_t>(i));
    // Levels of the tree whose two subtrees are built by two threads: twice as many subtrees
    // as threads, so that an uneven split still leaves every thread busy.
    int parallelLevels = 0;
    while (threads > 1 && (1u << parallelLevels) < 2 * threads) ++parallelLevels;
    Builder builder(items);
    builder.build(0, items.size(), 0, builder.boundsOf(0, items.size()), 0, parallelLevels);
    // The input positions in the order the build left them, which is the leaves' order.
    std::vector<int32_t> order(count);
    for (size_t i = 0; i < count; ++i) order[i] = items[i].index;
    release(items); // not held while the wide tree is made beside the binary one
    if (count <= kFewItems) {
        for (int32_t position : order) {
            const Bounds3 b = boundsOf(static_cast<size_t>(position)); // exact, not rounded to float
            const int32_t item = ids.empty() ? position : ids[static_cast<size_t>(position)];
            fewItems_.push_back({{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}, item});
        }
    }
    Collapser collapser(builder.nodes.get(), order, ids, nodes_, items_);
    nodes_.reserve(collapser.count(0));
    collapser.collapse(0, depth_);
    items_.shrink_to_fit();
}

} // namespace crt::tracer
