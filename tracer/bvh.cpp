// Wide BVHs built top-down from binned surface-area-heuristic splits (bvh_split.hpp).
#include "tracer/bvh.hpp"
#include "tracer/bvh_split.hpp"
#include "tracer/worker_threads.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <future>
#include <iterator>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace crt::tracer {

namespace {

using bvh_build::BuildItem;
using bvh_build::RangeBounds;
using bvh_build::Split;
using bvh_build::SplitFinder;

// Subtrees of fewer items are built by the thread that reaches them: they take a
// millisecond or less, not worth a thread of their own.
constexpr size_t kParallelItems = 8192;

/// Node reservations of more bytes are left as they are after the build.
constexpr size_t kSmallReservation = size_t{1} << 20;

/// Frees a vector's memory (assigning {} keeps it: that assigns an empty initializer list).
template <typename T> void release(std::vector<T>& v) { std::vector<T>().swap(v); }

/// A range of items that becomes a child of a wide node: a leaf, or (with a split) an inner
/// node. Its split is found when the range is made, since whether it is a leaf decides
/// which child its parent opens next.
struct Span {
    size_t begin, end;
    bvh_build::Box4 bounds;
    double area; ///< of its bounds, which decides the child opened next
    int depth;   ///< splits above it
    bool inner;  ///< split, into `split`'s two sides
    Split split;
};

/// The wide nodes and leaf lists of a tree, or of a subtree built on a thread of its own
/// (its indices then count from its own first node and item until it is appended).
template <int Width>
struct WideTree {
    std::vector<WideNode<Width>> nodes;
    std::vector<int32_t> items; ///< the leaves of more than one item: count, items

    /// Puts `part` after what is here, moving its indices along with it.
    void append(const WideTree& part) {
        const auto nodeShift = static_cast<uint32_t>(nodes.size());
        const auto itemShift = static_cast<uint32_t>(items.size());
        for (WideNode<Width> node : part.nodes) {
            const int used = node.usedSlots();
            for (int slot = 0; slot < Width; ++slot) {
                uint32_t& child = node.child[slot];
                if (!(used & (1 << slot)) || WideChild::isOneItem(child)) continue;
                child += WideChild::isLeaf(child) ? itemShift : nodeShift;
            }
            nodes.push_back(node);
        }
        items.insert(items.end(), part.items.begin(), part.items.end());
    }
};

/// Builds a wide tree top-down: a node over a range takes the two sides of its split, then
/// keeps opening the inner child of largest surface area until it has Width (as Embree's
/// builders do). Nodes are laid out depth-first, children in slot order. Near the
/// root, inner children are built on threads of their own, each into a WideTree appended
/// in slot order, so the tree and its layout are the ones a single thread makes.
template <int Width>
class WideBuilder {
public:
    /// `items`: the build's items, their `index` the position in the build's input;
    /// `ids`: what each position stands for (empty: the position itself).
    WideBuilder(std::span<BuildItem> items, const std::vector<int32_t>& ids, bool groupedLeaves)
        : finder_(items, groupedLeaves), items_(items), ids_(ids) {}

    Span root() {
        Span span;
        fill(span, 0, items_.size(), finder_.boundsOf(0, items_.size()), 0);
        return span;
    }

    /// Builds the node over `span` and its subtree at the end of `tree`; the inner children
    /// of nodes fewer than `parallelLevels` levels down get threads of their own. Returns
    /// the subtree's depth in wide levels.
    int build(const Span& span, WideTree<Width>& tree, int parallelLevels) {
        const size_t index = tree.nodes.size();
        tree.nodes.emplace_back();
        Span children[Width];
        const size_t childCount = gather(span, children);
        std::unique_ptr<Apart> apart;
        if (parallelLevels > 0) {
            apart = std::make_unique<Apart>();
            startApart(children, childCount, *apart, parallelLevels - 1);
        }
        WideNode<Width> node = emptyNode();
        int depth = 1;
        for (size_t slot = 0; slot < childCount; ++slot) {
            const Span& child = children[slot];
            for (int axis = 0; axis < 3; ++axis) {
                node.setFace(axis, static_cast<int>(slot), child.bounds.lo[axis]);
                node.setFace(3 + axis, static_cast<int>(slot), child.bounds.hi[axis]);
            }
            if (!child.inner) {
                node.child[slot] = leaf(child, tree);
                continue;
            }
            node.child[slot] = WideChild::node(static_cast<uint32_t>(tree.nodes.size()));
            if (apart && apart->built[slot].valid()) {
                depth = std::max(depth, 1 + apart->built[slot].get());
                tree.append(apart->parts[slot]);
                release(apart->parts[slot].nodes);
            } else {
                depth = std::max(depth, 1 + build(child, tree, std::max(parallelLevels - 1, 0)));
            }
        }
        tree.nodes[index] = node;
        return depth;
    }

private:
    /// Inner children built on threads of their own: each one's subtree and its depth. The
    /// futures come last, so that they go first and wait for their threads (should this
    /// thread leave by an exception) before the subtrees those threads write go.
    struct Apart {
        WideTree<Width> parts[Width];
        std::future<int> built[Width];
    };

    /// The children of the node over `span`: the two sides of its split (or the span itself,
    /// a lone leaf at the root), then the inner child of largest surface area opened until
    /// there are Width.
    size_t gather(const Span& span, Span (&children)[Width]) {
        if (!span.inner) {
            children[0] = span;
            return 1;
        }
        divide(span, children[0], children[1]);
        size_t childCount = 2;
        while (childCount < Width) {
            int widest = -1;
            for (size_t i = 0; i < childCount; ++i)
                if (children[i].inner && (widest < 0 || children[i].area > children[widest].area))
                    widest = static_cast<int>(i);
            if (widest < 0) break;
            const Span opened = children[widest]; // its place takes its first side
            divide(opened, children[widest], children[childCount++]);
        }
        return childCount;
    }

    /// The two sides of an inner span's split, each with its own split found.
    void divide(const Span& parent, Span& first, Span& second) {
        const Split& split = parent.split;
        fill(first, parent.begin, split.mid, split.below, parent.depth + 1);
        fill(second, split.mid, parent.end, split.above, parent.depth + 1);
    }

    /// Makes `span` the range [begin, end) of bounds `range`, finding its split.
    void fill(Span& span, size_t begin, size_t end, const RangeBounds& range, int depth) {
        span.begin = begin;
        span.end = end;
        span.bounds = range.bounds;
        span.area = range.bounds.surfaceArea();
        span.depth = depth;
        span.inner = finder_.split(begin, end, range, depth, span.split);
    }

    /// Starts building the inner children worth a thread on threads of their own, each into
    /// its part; the first inner child stays for this thread.
    void startApart(const Span (&children)[Width], size_t childCount, Apart& apart, int levelsBelow) {
        bool first = true;
        for (size_t slot = 0; slot < childCount; ++slot) {
            const Span& child = children[slot];
            if (!child.inner || child.end - child.begin < kParallelItems) continue;
            if (std::exchange(first, false)) continue;
            apart.parts[slot].nodes.reserve(child.end - child.begin - 1);
            try {
                apart.built[slot] = std::async(std::launch::async, [this, &child, &part = apart.parts[slot], levelsBelow] {
                    return build(child, part, levelsBelow);
                });
            } catch (const std::system_error&) {
                // no thread to be had: built on this one
            }
        }
    }

    static WideNode<Width> emptyNode() {
        WideNode<Width> node;
        const float inf = std::numeric_limits<float>::infinity();
        for (auto& group : node.faces) {
            for (int axis = 0; axis < 3; ++axis) {
                group[axis] = Float4{inf, inf, inf, inf};
                group[3 + axis] = Float4{-inf, -inf, -inf, -inf};
            }
        }
        for (uint32_t& child : node.child) child = WideChild::node(0);
        return node;
    }

    /// A leaf's `child` in the wide tree: its item, or where its items start in `tree.items`.
    uint32_t leaf(const Span& span, WideTree<Width>& tree) const {
        auto id = [&](size_t at) {
            const int32_t position = items_[at].index;
            return ids_.empty() ? position : ids_[static_cast<size_t>(position)];
        };
        const size_t count = span.end - span.begin;
        if (count == 1) return WideChild::item(static_cast<uint32_t>(id(span.begin)));
        const auto start = static_cast<uint32_t>(tree.items.size());
        tree.items.push_back(static_cast<int32_t>(count));
        for (size_t at = span.begin; at < span.end; ++at) tree.items.push_back(id(at));
        return WideChild::items(start);
    }

    SplitFinder finder_;
    std::span<const BuildItem> items_;
    const std::vector<int32_t>& ids_;
};

/// Calls visit(child) for each used slot of `nodes` that leads to a leaf (`child` a reference
/// into the node, which visit may rewrite when the nodes are not const).
template <typename Nodes, typename Visit> void forEachLeafChild(Nodes& nodes, Visit&& visit) {
    for (auto& node : nodes) {
        const int used = node.usedSlots();
        for (int slot = 0; slot < static_cast<int>(std::size(node.child)); ++slot)
            if ((used & (1 << slot)) && WideChild::isLeaf(node.child[slot])) visit(node.child[slot]);
    }
}

/// The groups of up to four that `items` items make.
constexpr size_t groupsOf(size_t items) { return (items + 3) / 4; }

/// The items' float boxes, items[i] from boundsOf(i), on up to `threads` threads when there
/// are many.
void makeItems(std::span<BuildItem> items, FunctionRef<Bounds3(size_t)> boundsOf, unsigned threads) {
    const size_t parts = std::clamp<size_t>(items.size() / kParallelItems, 1, std::max(threads, 1u));
    runOnThreads(parts, [&](size_t part) {
        const size_t end = items.size() * (part + 1) / parts;
        for (size_t i = items.size() * part / parts; i < end; ++i)
            items[i] = BuildItem(boundsOf(i), static_cast<int32_t>(i));
    });
}

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

template <int Width>
void WideBvh<Width>::buildFrom(size_t count, ItemBounds boundsOf, unsigned threads, std::vector<int32_t> ids,
                               bool groupedLeaves) {
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
    std::unique_ptr<BuildItem[]> itemStore = std::make_unique_for_overwrite<BuildItem[]>(count);
    const std::span<BuildItem> items(itemStore.get(), count);
    makeItems(items, boundsOf, threads);
    // Levels of wide nodes whose inner children are built on threads of their own: at least
    // twice as many subtrees as threads, so that an uneven split still leaves every thread
    // busy.
    int parallelLevels = 0;
    for (unsigned subtrees = 1; threads > 1 && subtrees < 2 * threads; subtrees *= Width) ++parallelLevels;
    WideBuilder<Width> builder(items, ids, groupedLeaves);
    WideTree<Width> tree;
    tree.nodes.reserve(std::max<size_t>(count - 1, 1)); // the most a tree over `count` items takes
    depth_ = builder.build(builder.root(), tree, parallelLevels);
    if (count <= kFewItems) {
        // In the order the build left them, which is the leaves' order; their boxes exact,
        // not rounded to float.
        for (const BuildItem& item : items) {
            const auto position = static_cast<size_t>(item.index);
            const Bounds3 b = boundsOf(position);
            const int32_t id = ids.empty() ? item.index : ids[position];
            fewItems_.push_back({{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}, id});
        }
    }
    itemStore.reset();
    nodes_ = std::move(tree.nodes);
    items_ = std::move(tree.items);
    // A large reservation is mapped apart and its pages get memory only when written, so
    // its untouched tail costs nothing; only a small one is given back (a short copy).
    if (nodes_.capacity() * sizeof(Node) < kSmallReservation) nodes_.shrink_to_fit();
    items_.shrink_to_fit();
}

template <int Width>
std::span<const int32_t> WideBvh<Width>::leafItems(uint32_t child, int32_t& lone) const {
    const uint32_t index = WideChild::index(child);
    if (!WideChild::isOneItem(child))
        return {&items_[index + 1], static_cast<size_t>(items_[index])};
    lone = static_cast<int32_t>(index);
    return {&lone, 1};
}

template <int Width>
size_t WideBvh<Width>::leafGroupCount() const {
    size_t groups = 0;
    forEachLeafChild(nodes_, [&](uint32_t child) {
        int32_t lone;
        groups += groupsOf(leafItems(child, lone).size());
    });
    return groups;
}

template <int Width>
void WideBvh<Width>::groupLeaves(MakeGroup makeGroup) {
    // A leaf's groups, four items each but the last: one is the leaf's item, more its list.
    std::vector<int32_t> groupedItems;
    auto grouped = [&](std::span<const int32_t> items) {
        const size_t groups = groupsOf(items.size());
        auto group = [&](size_t g) { return makeGroup(items.subspan(4 * g, std::min<size_t>(4, items.size() - 4 * g))); };
        if (groups == 1) return WideChild::item(static_cast<uint32_t>(group(0)));
        const auto start = static_cast<uint32_t>(groupedItems.size());
        groupedItems.push_back(static_cast<int32_t>(groups));
        for (size_t g = 0; g < groups; ++g) groupedItems.push_back(group(g));
        return WideChild::items(start);
    };
    forEachLeafChild(nodes_, [&](uint32_t& child) {
        int32_t lone;
        child = grouped(leafItems(child, lone));
    });
    groupedItems.shrink_to_fit();
    items_ = std::move(groupedItems);
    if (!fewItems_.empty()) {
        // At most four items: the root's one leaf grouped them all. Its box is theirs joined.
        Bounds3 joint;
        for (const FewItem& few : fewItems_)
            joint.include(Bounds3{{few.faces[0], few.faces[1], few.faces[2]}, {few.faces[3], few.faces[4], few.faces[5]}});
        const auto group = static_cast<int32_t>(WideChild::index(nodes_[0].child[0]));
        fewItems_ = {{{joint.lo.x, joint.lo.y, joint.lo.z, joint.hi.x, joint.hi.y, joint.hi.z}, group}};
    }
}

template class WideBvh<4>;
template class WideBvh<8>;

} // namespace crt::tracer
