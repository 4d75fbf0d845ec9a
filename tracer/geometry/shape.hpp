// The interface every primitive implements, in its own object space.
//
// A primitive reports every place the whole line o + t·d (t from −∞ to +∞) crosses its
// surface, sorted by t, and whether the line starts inside the solid. Both CSG (which walks
// the crossings of its operands) and plain nearest-hit queries (the first crossing past
// t = 0) are built on this one query, so a shape is written once. Surface details (normal,
// UV, the refined point and its error bound) are computed only for the crossing that wins.
#pragma once

#include "tracer/geometry/bounds.hpp"
#include "tracer/geometry/function_ref.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace crt::tracer {

/// One crossing of the line with a surface. `part` tells the shape which face it was
/// (a box side, a cylinder cap, a prism's wall …) so surfaceAt need not redo the search.
/// (No member initialisers: a CrossingList is made for every intersection test and its
/// unused slots need not be written.)
struct Crossing {
    double t;
    uint32_t part;
};

/// No part: a face index that names none.
inline constexpr uint32_t kNoPart = ~0u;

/// The crossings of one line, ascending. Eight are kept in place (a torus has four, a
/// star-shaped superellipsoid up to six, most primitives two or fewer); a shape with more,
/// such as a prism with many walls, spills the rest to the heap.
class CrossingList {
  public:
    static constexpr int kInPlace = 8;

    CrossingList() = default;
    CrossingList(const CrossingList&) = delete; // data_ may point into the list itself
    CrossingList& operator=(const CrossingList&) = delete;

    int count = 0;
    /// Whether the line is inside the solid before its first crossing (a half-space can
    /// start inside; bounded solids never do). Each crossing of a solid toggles inside/outside.
    bool startsInside = false;

    void add(double t, uint32_t part) {
        if (count == capacity_) grow();
        data_[count++] = {t, part};
    }
    const Crossing& operator[](int i) const { return data_[i]; }
    Crossing& operator[](int i) { return data_[i]; }
    /// Sorts the crossings by t, for shapes that find them out of order.
    void sortByT();

  private:
    /// Moves the crossings to the heap, with twice the room (kept when the list is reused).
    void grow();

    Crossing inPlace_[kInPlace];
    Crossing* data_ = inPlace_;
    int capacity_ = kInPlace;
    std::unique_ptr<Crossing[]> heap_;
};

/// Called with crossings in order, until it returns false.
using CrossingVisitor = FunctionRef<bool(const Crossing&)>;

/// The surface where a crossing happened, in object space.
struct SurfacePoint {
    Vec3 point{0.0};      ///< refined onto the surface
    Vec3 pointError{0.0}; ///< per-component bound of the absolute rounding error of `point`
    Vec3 normal{0, 1, 0}; ///< geometric normal, unit length; outward for solids
    Vec3 shadingNormal{0, 1, 0}; ///< interpolated (mesh vertex normals), else equal to normal
    Vec2 uv{0.0};
    /// ∂point/∂u and ∂point/∂v: how the point moves with its uv (a bump read through uv tilts
    /// the normal along them). Set with uv; (0, 0, 0) where uv is not a parameterisation.
    Vec3 dpdu{0.0};
    Vec3 dpdv{0.0};
};

} // namespace crt::tracer
