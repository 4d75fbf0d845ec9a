// Wide bounding volume hierarchies (4 or 8 children a node): binned SAH build, laid out
// depth-first in an array.
#pragma once

#include "tracer/geometry/bounds.hpp"
#include "tracer/geometry/function_ref.hpp"
#include "tracer/stats.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace crt::tracer {

/// A ray prepared for box tests: the reciprocal direction, and for each axis which face of a
/// box the ray meets first, so the slab test needs no branch on the direction.
struct BoxRay {
    Vec3 origin;
    Vec3 invDir;
    int nearFace[3]; ///< index into Bounds3 viewed as {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}
    int farFace[3];

    explicit BoxRay(const Ray& ray)
        : origin(ray.origin), invDir(1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z) {
        for (int i = 0; i < 3; ++i) {
            const int negative = invDir[i] < 0; // then the `hi` face comes first
            nearFace[i] = i + 3 * negative;
            farFace[i] = i + 3 - 3 * negative;
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

/// A ray whose BoxRay is prepared on first use: a query that meets no box test in double
/// precision (a four-wide traversal that reaches no CSG object) does not pay for it.
class LazyBoxRay {
public:
    explicit LazyBoxRay(const Ray& ray) : ray_(ray) {}
    const Ray& ray() const { return ray_; }
    const BoxRay& box() const {
        if (!box_) box_.emplace(ray_);
        return *box_;
    }

private:
    const Ray& ray_;
    mutable std::optional<BoxRay> box_;
};

/// Four float lanes; GCC and Clang compile the arithmetic to one SSE instruction each.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

/// Bit i set when lane i of a comparison result is true.
inline int laneMask(Int4 lanes) {
#if defined(__SSE__)
    return __builtin_ia32_movmskps(reinterpret_cast<Float4>(lanes));
#else
    return (lanes[0] & 1) | (lanes[1] & 2) | (lanes[2] & 4) | (lanes[3] & 8);
#endif
}

/// What a slot of a wide node leads to, in 32 bits: an inner node's index, or (top bit set)
/// a leaf. A leaf of one item holds the item itself (most leaves: no look-up in `items`,
/// and 4 bytes less an item); a leaf of more, where it starts in `items`: its count, then
/// its items.
struct WideChild {
    /// Items are numbers below this (and there are fewer than half as many).
    static constexpr uint32_t kMaxItems = 1u << 30;

    static uint32_t node(uint32_t index) { return index; }
    static uint32_t item(uint32_t item) { return kLeaf | kOneItem | item; }
    static uint32_t items(uint32_t start) { return kLeaf | start; }
    static bool isLeaf(uint32_t child) { return (child & kLeaf) != 0; }
    static bool isOneItem(uint32_t child) { return (child & kOneItem) != 0; }
    /// The item of a leaf of one, where the leaf starts in `items` for others.
    static uint32_t index(uint32_t child) { return child & (kMaxItems - 1); }

private:
    static constexpr uint32_t kLeaf = 1u << 31;
    static constexpr uint32_t kOneItem = 1u << 30;
};

/// A node of a wide BVH: the boxes of up to Width children (4 or 8) side by side, axis by
/// axis in groups of four, so that one ray is tested against four boxes at once, and where
/// each leads (WideChild). Boxes are the double-precision bounds rounded outwards to float;
/// an unused slot has an empty box (lo > hi) that no ray hits.
template <int Width>
struct alignas(16) WideNode {
    static_assert(Width == 4 || Width == 8);
    /// Groups of four slots.
    static constexpr int kGroups = Width / 4;

    Float4 faces[kGroups][6]; ///< per group: lo.x, lo.y, lo.z, hi.x, hi.y, hi.z of its four boxes
    uint32_t child[Width];

    /// Bit i set when slot i holds a child (its box is not empty).
    int usedSlots() const {
        int mask = 0;
        for (int group = 0; group < kGroups; ++group)
            mask |= laneMask(faces[group][0] <= faces[group][3]) << (4 * group);
        return mask;
    }
    /// How many slots hold a child.
    int used() const {
        // Looked up: std::popcount is a call into libgcc on processors the build does not
        // assume have POPCNT, and a counted traversal asks for every node it tests.
        static constexpr int8_t kBitsSet[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
        const int mask = usedSlots();
        int count = 0;
        for (int group = 0; group < kGroups; ++group) count += kBitsSet[(mask >> (4 * group)) & 15];
        return count;
    }
    /// Face f (0-5, as in `faces`) of slot `slot`'s box.
    void setFace(int f, int slot, float value) { faces[slot / 4][f][slot % 4] = value; }
};

/// A ray prepared for four-box tests in float. The ray origin is rounded to float with a
/// margin on the safe side of each slab (shifted forwards for the near faces, backwards for
/// the far ones), so no box the double-precision ray meets is ever missed; the rounding of
/// the float arithmetic itself is covered by widening the exit distances, as in pbrt-v4
/// (here through the reciprocal they are multiplied by).
struct WideRay {
    Float4 nearOrigin[3], farOrigin[3], invDir[3];
    Float4 widenedInvDir[3]; ///< invDir · kWiden, rounded: for exit distances
    /// Byte offsets into a group of WideNode::faces of the face met first (`hi` when the ray
    /// runs towards -axis) and last; offsets rather than indices save the scaling per node.
    size_t nearFace[3];
    size_t farFace[3];

    explicit WideRay(const Ray& ray);

    /// Entry distances of a node's boxes, four to each group; returns the mask of boxes the
    /// segment (0, tMax) meets (bit i for slot i), given limit = widenedLimit(tMax) in every
    /// lane.
    template <int Width>
    int hits(const WideNode<Width>& node, Float4 limit, Float4 (&entry)[Width / 4]) const {
        int mask = 0;
        for (int group = 0; group < Width / 4; ++group)
            mask |= hits(node.faces[group], limit, entry[group]) << (4 * group);
        return mask;
    }

    /// The same for one group of four boxes.
    int hits(const Float4 (&faces)[6], Float4 limit, Float4& entry) const {
        Float4 enter = {0, 0, 0, 0};
        Float4 exit = limit;
        for (int axis = 0; axis < 3; ++axis) {
            Float4 tNear = (face(faces, nearFace[axis]) - nearOrigin[axis]) * invDir[axis];
            Float4 tFar = (face(faces, farFace[axis]) - farOrigin[axis]) * widenedInvDir[axis];
            // A NaN (0 · ∞: the ray lies in a face plane) fails the comparison and leaves the
            // running value alone, which keeps the test conservative.
            enter = tNear > enter ? tNear : enter;
            exit = tFar < exit ? tFar : exit;
        }
        entry = enter;
        return laneMask(enter <= exit);
    }

    /// A float at least as large as tMax and as any float distance computed for a true
    /// distance below it: 2·γ(3) of float arithmetic above tMax.
    static float widenedLimit(double tMax) {
        return tMax < std::numeric_limits<float>::max() ? float(tMax) * kWiden
                                                        : std::numeric_limits<float>::infinity();
    }

    static Float4 widenedLimit4(double tMax) {
        const float limit = widenedLimit(tMax);
        return Float4{limit, limit, limit, limit};
    }

    static constexpr float kWiden = 1 + 2 * 3 * std::numeric_limits<float>::epsilon();

private:
    static const Float4& face(const Float4 (&faces)[6], size_t offset) {
        return *reinterpret_cast<const Float4*>(reinterpret_cast<const char*>(faces) + offset);
    }
};

/// A BVH of nodes of Width children (4 or 8): binned SAH build, laid out depth-first.
template <int Width>
class WideBvh {
public:
    using Node = WideNode<Width>;

    /// Builds over n items with the given (finite) bounds, on up to `threads` threads; the
    /// tree is the same whatever their number. Item i is ids[i], or i when there are no ids;
    /// items are below WideChild::kMaxItems (std::length_error otherwise).
    void build(const std::vector<Bounds3>& itemBounds, unsigned threads = 1, std::vector<int32_t> ids = {}) {
        build(itemBounds.size(), [&](size_t i) { return itemBounds[i]; }, threads, std::move(ids));
    }
    /// The same, asking boundsOf(i) for item i's bounds (once, or twice with few items) rather
    /// than holding them all: a mesh's triangles need not have their boxes stored twice. With
    /// many items and threads, boundsOf is called from several threads at once.
    template <typename BoundsOf>
    void build(size_t count, BoundsOf&& boundsOf, unsigned threads = 1, std::vector<int32_t> ids = {}) {
        buildFrom(count, ItemBounds(boundsOf), threads, std::move(ids));
    }

    /// Builds as build() does, but a range of up to four items is always one leaf, for items
    /// tested four at a time. Returns how many groups of up to four the leaves' items make
    /// (a leaf of more, which the depth limit or coinciding centroids can leave, makes
    /// several); groupLeaves then replaces them by the groups.
    template <typename BoundsOf>
    size_t buildGrouped(size_t count, BoundsOf&& boundsOf, unsigned threads, std::vector<int32_t> ids = {}) {
        buildFrom(count, ItemBounds(boundsOf), threads, std::move(ids), true);
        return leafGroupCount();
    }
    /// What stands for up to four items: given the items, the item replacing them (below
    /// WideChild::kMaxItems).
    using MakeGroup = FunctionRef<int32_t(std::span<const int32_t>)>;
    /// Replaces each leaf's items, four by four in order, by the groups makeGroup makes of
    /// them, called in the leaves' depth-first order: traversal then visits groups.
    void groupLeaves(MakeGroup makeGroup);

    bool empty() const { return nodes_.empty(); }
    size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }
    /// The bytes its nodes and items take (beyond the Bvh itself); the nodes' spare capacity,
    /// never written, is not counted.
    uint64_t byteSize() const {
        return nodes_.size() * sizeof(Node) + items_.capacity() * sizeof(int32_t) +
               fewItems_.capacity() * sizeof(FewItem);
    }

    /// Visits the items whose leaves the ray segment (0, tMax) reaches, nearer subtrees
    /// first; `tMax` may shrink while visiting (a nearest-hit search). visit(item) returns
    /// false to stop; traverse then returns false. The box slots tested are added to
    /// stats.nodesVisited.
    template <typename Visit>
    bool traverse(const LazyBoxRay& ray, const double& tMax, RayStats& stats, Visit&& visit) const {
        return search<true>(ray, tMax, stats.nodesVisited, visit);
    }
    /// The same without counting the box slots tested: for a search whose count nobody reads.
    template <typename Visit>
    bool traverseUncounted(const LazyBoxRay& ray, const double& tMax, Visit&& visit) const {
        uint64_t uncounted = 0;
        return search<false>(ray, tMax, uncounted, visit);
    }

    /// Up to this many items, traversal tests each item's box (fewItems_).
    static constexpr size_t kFewItems = 4;

private:
    using ItemBounds = FunctionRef<Bounds3(size_t)>;
    void buildFrom(size_t count, ItemBounds boundsOf, unsigned threads, std::vector<int32_t> ids,
                   bool groupedLeaves = false);
    /// How many groups of up to four the leaves' items make.
    size_t leafGroupCount() const;
    /// The items of the leaf that `child` leads to, a copy of a lone item going in `lone`.
    std::span<const int32_t> leafItems(uint32_t child, int32_t& lone) const;

    /// The deepest the wide tree may be: a branch of up to 56 splits (SplitFinder::kMaxDepth)
    /// takes at most that many wide levels, and each level pushes at most Width - 1.
    static constexpr int kMaxWideDepth = 64;

    template <bool kCounted, typename Visit>
    bool search(const LazyBoxRay& ray, const double& tMax, uint64_t& visited, Visit& visit) const {
        if (nodes_.empty()) return true;
        if (!fewItems_.empty()) {
            // A handful of items: their boxes one by one in double precision, which is
            // cheaper than preparing a ray for four-wide float tests.
            const BoxRay& boxRay = ray.box();
            if constexpr (kCounted) visited += fewItems_.size();
            for (const FewItem& few : fewItems_)
                if (boxRay.hits(few.faces, 0.0, tMax) && !visit(few.item)) return false;
            return true;
        }
        return searchWide<kCounted>(ray.ray(), tMax, visited, visit);
    }

    // Kept out of line so that the few-items path does not pay for its stack frame.
    template <bool kCounted, typename Visit>
    [[gnu::noinline]] bool searchWide(const Ray& ray, const double& tMax, uint64_t& visited, Visit& visit) const {
        const WideRay wideRay(ray);
        uint64_t tested = 0; // counted locally: `visited` lives in memory
        // Children met are taken nearest first; the others wait on the stack with their
        // entry distance and are dropped when popped if a nearer hit was found meanwhile.
        struct Pending {
            uint32_t child;
            float entry;
        };
        Pending stack[(Width - 1) * kMaxWideDepth + Width];
        int top = 0;
        Pending current{WideChild::node(0), 0};
        Float4 limit = WideRay::widenedLimit4(tMax); // tMax changes only in visit()
        while (true) {
            if (WideChild::isLeaf(current.child)) {
                if (!visitLeaf(current.child, visit)) {
                    visited += tested;
                    return false;
                }
                limit = WideRay::widenedLimit4(tMax);
            } else {
                const Node& node = nodes_[current.child];
                if constexpr (kCounted) tested += static_cast<uint64_t>(node.used());
                Float4 entries[Width / 4];
                int met = wideRay.hits(node, limit, entries);
                auto entry = [&](int slot) { return entries[slot / 4][slot % 4]; };
                if (met != 0 && (met & (met - 1)) == 0) { // one child: no ordering
                    const int slot = __builtin_ctz(static_cast<unsigned>(met));
                    current = {node.child[slot], entry(slot)};
                    continue;
                }
                const int second = met & (met - 1);
                if (met != 0 && (second & (second - 1)) == 0) { // two children: the nearer first
                    const int a = __builtin_ctz(static_cast<unsigned>(met));
                    const int b = __builtin_ctz(static_cast<unsigned>(second));
                    const Pending pa{node.child[a], entry(a)}, pb{node.child[b], entry(b)};
                    const bool bFirst = pb.entry < pa.entry;
                    stack[top++] = bFirst ? pa : pb;
                    current = bFirst ? pb : pa;
                    continue;
                }
                if (met != 0) {
                    // Order the children met by entry distance (a few: insertion sort).
                    Pending order[Width];
                    int n = 0;
                    for (int rest = met; rest != 0; rest &= rest - 1) {
                        const int slot = __builtin_ctz(static_cast<unsigned>(rest));
                        Pending p{node.child[slot], entry(slot)};
                        int at = n++;
                        while (at > 0 && order[at - 1].entry > p.entry) {
                            order[at] = order[at - 1];
                            --at;
                        }
                        order[at] = p;
                    }
                    for (int i = n - 1; i > 0; --i) stack[top++] = order[i];
                    current = order[0];
                    continue;
                }
            }
            // Next: the nearest pending subtree still in front of the nearest hit so far.
            do {
                if (top == 0) {
                    visited += tested;
                    return true;
                }
                --top;
            } while (stack[top].entry > limit[0]);
            current = stack[top];
        }
    }

    template <typename Visit>
    bool visitLeaf(uint32_t child, Visit& visit) const {
        const uint32_t index = WideChild::index(child);
        if (WideChild::isOneItem(child)) return visit(static_cast<int32_t>(index));
        const auto count = static_cast<uint32_t>(items_[index]);
        for (uint32_t i = 1; i <= count; ++i)
            if (!visit(items_[index + i])) return false;
        return true;
    }

    std::vector<Node> nodes_;
    std::vector<int32_t> items_; ///< the leaves of more than one item: count, items
    struct FewItem {
        double faces[6]; ///< as BoxRay indexes them
        int32_t item;
    };
    std::vector<FewItem> fewItems_; ///< with at most kFewItems items, them and their boxes
    int depth_ = 0;
};

/// The BVH of a scene's objects: four-wide, which keeps a node at 112 bytes.
using Bvh = WideBvh<4>;

} // namespace crt::tracer
