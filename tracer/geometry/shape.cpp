// The crossing list's rarely used parts: spilling beyond its places, and sorting.
#include "tracer/geometry/shape.hpp"

namespace crt::tracer {

void CrossingList::spill(const Crossing& c) {
    // A list reused after `count` was reset drops what it spilled before.
    spilled_.resize(static_cast<size_t>(count - kInPlace));
    spilled_.push_back(c);
}

void CrossingList::sortByT() {
    // Insertion sort: the lists are short and often nearly sorted.
    for (int i = 1; i < count; ++i) {
        const Crossing c = (*this)[i];
        int j = i;
        for (; j > 0 && (*this)[j - 1].t > c.t; --j) (*this)[j] = (*this)[j - 1];
        (*this)[j] = c;
    }
}

} // namespace crt::tracer
