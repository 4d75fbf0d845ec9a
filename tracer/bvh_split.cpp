#include "tracer/bvh_split.hpp"

#include <algorithm>

namespace crt::tracer::bvh_build {

namespace {

constexpr int kBins = 12;

} // namespace

bool SplitFinder::split(size_t begin, size_t end, const RangeBounds& range, int depth, Split& split) {
    int axis = 0;
    if (range.centroids.extent(1) > range.centroids.extent(axis)) axis = 1;
    if (range.centroids.extent(2) > range.centroids.extent(axis)) axis = 2;
    const bool spread = range.centroids.extent(axis) > 0;
    const size_t count = end - begin;
    if (count <= 1 || !spread || depth >= kMaxDepth || (groupedLeaves_ && count <= kMaxLeafItems)) return false;
    return chooseSplit(begin, end, axis, range, split);
}

RangeBounds SplitFinder::boundsOf(size_t begin, size_t end) const {
    RangeBounds range;
    for (size_t i = begin; i < end; ++i) range.include(items_[i]);
    return range;
}

/// The split the surface area heuristic prefers, or none when a leaf is cheaper (the cost
/// of a leaf is its items; of a split, half an item plus each side's items weighted by
/// the share of the node's area its bounds take). Falls back on the median where the
/// heuristic's split leaves a side empty.
bool SplitFinder::chooseSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split) {
    const size_t count = end - begin;
    if (count <= static_cast<size_t>(kBins)) return sortedSplit(begin, end, axis, range, split);
    if (!binnedSplit(begin, end, axis, range, split)) return false;
    if (split.mid == begin || split.mid == end) medianSplit(begin, end, axis, split);
    return true;
}

/// Whether a split of this cost (the sum over its sides of items times area) beats a leaf.
bool SplitFinder::splitPays(double cost, const RangeBounds& range, size_t count) {
    const double area = range.bounds.surfaceArea();
    return count > kMaxLeafItems || 0.5 + (area > 0 ? cost / area : 0) < static_cast<double>(count);
}

/// Halves at the median centroid along `axis`.
void SplitFinder::medianSplit(size_t begin, size_t end, int axis, Split& split) {
    const size_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [axis](const BuildItem& a, const BuildItem& b) { return a.centroid()[axis] < b.centroid()[axis]; });
    split = {mid, boundsOf(begin, mid), boundsOf(mid, end)};
}

/// A few items: sorted along the axis, every split between two of them is weighed (bins
/// would be mostly empty, and setting them up costs more than the items).
bool SplitFinder::sortedSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split) {
    const size_t count = end - begin;
    // Their order by centroid, sorted by insertion on keys computed once; the items are
    // moved only where they are not in that order already.
    float keys[kBins];
    uint8_t order[kBins];
    bool inOrder = true;
    for (size_t i = 0; i < count; ++i) {
        const float key = items_[begin + i].centroid()[axis];
        size_t at = i;
        for (; at > 0 && keys[at - 1] > key; --at) {
            keys[at] = keys[at - 1];
            order[at] = order[at - 1];
        }
        keys[at] = key;
        order[at] = static_cast<uint8_t>(i);
        inOrder = inOrder && at == i;
    }
    BuildItem sorted[kBins];
    for (size_t i = 0; i < count; ++i) sorted[i] = items_[begin + order[i]];
    if (!inOrder) std::copy(sorted, sorted + count, items_.begin() + static_cast<ptrdiff_t>(begin));
    // The area of the items from i on, then the cost of splitting before each i.
    double aboveArea[kBins];
    Box4 above;
    for (size_t i = count - 1; i >= 1; --i) {
        above.include(sorted[i].loLanes(), sorted[i].hiLanes());
        aboveArea[i] = above.surfaceArea();
    }
    Box4 below;
    size_t best = 0;
    double bestCost = kInfinity;
    for (size_t i = 1; i < count; ++i) {
        below.include(sorted[i - 1].loLanes(), sorted[i - 1].hiLanes());
        const double cost = double(i) * below.surfaceArea() + double(count - i) * aboveArea[i];
        if (cost < bestCost) {
            bestCost = cost;
            best = i;
        }
    }
    if (!splitPays(bestCost, range, count)) return false;
    const size_t mid = begin + best;
    split = {mid, boundsOf(begin, mid), boundsOf(mid, end)};
    return true;
}

/// Many items: binned by centroid along the axis, the splits between bins weighed.
bool SplitFinder::binnedSplit(size_t begin, size_t end, int axis, const RangeBounds& range, Split& split) {
    const size_t count = end - begin;
    RangeBounds bins[kBins];
    int binCount[kBins] = {};
    const double lo = range.centroids.lo[axis];
    const double scale = kBins / range.centroids.extent(axis);
    // Neighbouring items mostly fall into the same bin, and a bin grown in memory item by item
    // waits for its last update each time: a run of items in one bin grows bounds held apart,
    // and the bin takes them once the run ends. Joined in the items' order, the bins come out
    // as if grown item by item.
    int run = -1, runCount = 0;
    RangeBounds runBounds;
    auto endRun = [&] {
        bins[run].include(runBounds);
        binCount[run] += runCount;
    };
    for (size_t i = begin; i < end; ++i) {
        BuildItem& item = items_[i];
        // Both halves read before the bin is written into the second: a read overlapping
        // a write just made waits for it.
        const Float4 l = item.loLanes(), h = item.hiLanes();
        const Float4 centroid = BuildItem::centroidOf(l, h);
        const int b = std::clamp(static_cast<int>((centroid[axis] - lo) * scale), 0, kBins - 1);
        item.bin = static_cast<uint32_t>(b);
        if (b != run) {
            if (run >= 0) endRun();
            run = b;
            runCount = 0;
            runBounds = {};
        }
        ++runCount;
        runBounds.bounds.include(l, h);
        runBounds.centroids.include(centroid, centroid);
    }
    endRun();
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
    if (!splitPays(bestCost, range, count)) return false;
    split.below = {};
    split.above = {};
    for (int i = 0; i < kBins; ++i) (i <= best ? split.below : split.above).include(bins[i]);
    auto second = std::partition(items_.begin() + begin, items_.begin() + end,
                                 [&](const BuildItem& item) { return static_cast<int>(item.bin) <= best; });
    split.mid = static_cast<size_t>(second - items_.begin());
    return true;
}

} // namespace crt::tracer::bvh_build
