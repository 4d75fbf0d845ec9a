// How the BVH build divides its items: their boxes in float, and the split of a range of
// them that the surface area heuristic prefers, binned (pbrt-v4's BVHAggregate, simplified).
#pragma once

#include "tracer/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace crt::tracer::bvh_build {

/// The float next to f towards -infinity or +infinity (as std::nextafter, without a call into
/// the maths library for each face of each item).
inline float nextDown(float f) {
    if (f == 0) return -std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<int32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}
inline float nextUp(float f) { return -nextDown(-f); }

inline float roundDown(double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? nextDown(f) : f;
}

inline float roundUp(double v) {
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

/// An item of the build: its bounds rounded outwards to float. The faces and the two
/// integers are laid out so that each group of four is one Float4 load, the integer's lane
/// ignored: an item takes 32 bytes.
struct alignas(16) BuildItem {
    float lo[3];
    int32_t index; ///< the item's position in the build's input
    float hi[3];
    uint32_t bin; ///< set by SplitFinder for the range being split

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

/// Where a range of items is split, and the bounds of the two sides.
struct Split {
    size_t mid = 0; ///< the first item of the second side
    RangeBounds below, above;
};

/// Chooses how a range of items is divided, reordering them so that each side is a range
/// of its own. Ranges that do not overlap may be split on different threads at once.
class SplitFinder {
public:
    /// The most splits from the root to a leaf: below the traversal stack's 64 entries.
    static constexpr int kMaxDepth = 56;
    /// The most items a leaf holds (beyond the depth limit).
    static constexpr size_t kMaxLeafItems = 4;

    /// `groupedLeaves`: the items are tested four at a time, so a range of up to four is
    /// always one leaf (it costs about one test, like a node).
    explicit SplitFinder(std::span<BuildItem> items, bool groupedLeaves = false)
        : items_(items), groupedLeaves_(groupedLeaves) {}

    /// Splits items [begin, end), whose bounds are `range`, `depth` splits below the root,
    /// into `split`; false when they are to be one leaf (a single item, items whose
    /// centroids coincide, the depth limit, a leaf the heuristic finds cheaper, or up to four
    /// grouped items).
    bool split(size_t begin, size_t end, const RangeBounds& range, int depth, Split& split);

    RangeBounds boundsOf(size_t begin, size_t end) const;

private:
    bool chooseSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split);
    static bool splitPays(double cost, const RangeBounds& range, size_t count);
    void medianSplit(size_t begin, size_t end, int axis, Split& split);
    bool sortedSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split);
    bool binnedSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split);

    std::span<BuildItem> items_;
    bool groupedLeaves_;
};

} // namespace crt::tracer::bvh_build
