// The crossing list's rarely used parts: spilling beyond its places, and sorting.
#include "tracer/geometry/shape.hpp"

#include <algorithm>

namespace crt::tracer {

void CrossingList::grow() {
    auto more = std::make_unique<Crossing[]>(static_cast<size_t>(2 * capacity_));
    std::copy(data_, data_ + count, more.get());
    heap_ = std::move(more);
    data_ = heap_.get();
    capacity_ *= 2;
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
