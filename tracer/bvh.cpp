// Binned surface-area-heuristic BVH build (pbrt-v4's BVHAggregate, simplified).
#include "tracer/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace crt::tracer {

namespace {

constexpr int kBins = 12;
constexpr int kMaxLeafItems = 4;
constexpr int kMaxDepth = 56; // below the traversal stack's 64 entries

struct BuildItem {
    Bounds3 bounds;
    Vec3 centroid;
    int32_t index;
};

class Builder {
public:
    Builder(std::vector<BuildItem>& items, std::vector<BvhNode>& nodes, std::vector<int32_t>& order)
        : items_(items), nodes_(nodes), order_(order) {}

    int build(size_t begin, size_t end, int depth) {
        int32_t nodeIndex = static_cast<int32_t>(nodes_.size());
        nodes_.emplace_back();
        Bounds3 bounds, centroids;
        for (size_t i = begin; i < end; ++i) {
            bounds.include(items_[i].bounds);
            centroids.include(items_[i].centroid);
        }
        double* faces = nodes_[nodeIndex].faces;
        for (int i = 0; i < 3; ++i) {
            faces[i] = bounds.lo[i];
            faces[3 + i] = bounds.hi[i];
        }
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
        nodes_[nodeIndex].axis = static_cast<uint8_t>(axis);
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
    std::vector<BvhNode>& nodes_;
    std::vector<int32_t>& order_;
};

} // namespace

void Bvh::build(const std::vector<Bounds3>& itemBounds) {
    nodes_.clear();
    items_.clear();
    depth_ = 0;
    if (itemBounds.empty()) return;
    std::vector<BuildItem> items(itemBounds.size());
    for (size_t i = 0; i < itemBounds.size(); ++i)
        items[i] = {itemBounds[i], itemBounds[i].centroid(), static_cast<int32_t>(i)};
    nodes_.reserve(2 * items.size());
    items_.reserve(items.size());
    Builder builder(items, nodes_, items_);
    depth_ = builder.build(0, items.size(), 0);
}

} // namespace crt::tracer
