// Where a pattern value falls among the entries of a map: POV-Ray's lookup of its blend maps,
// shared by colour maps and material maps.
#pragma once

#include <cstddef>
#include <vector>

namespace crt::tracer {

/// The map's value there is entry `below` mixed with entry `above` by `fraction` (0: all
/// `below`); both are one entry where the value is at or outside a stop.
struct MapPosition {
    size_t below = 0;
    size_t above = 0;
    double fraction = 0;
};

/// `values` are non-decreasing and not empty. Outside them the first or last entry; where
/// entries share a value, the first of them at the value itself and the last just past it.
inline MapPosition mapPosition(const std::vector<double>& values, double value) {
    size_t last = values.size() - 1;
    if (!(value < values[last])) return {last, last, 0}; // NaN too: the map's end
    size_t next = 0;
    while (value > values[next]) ++next;
    if (next == 0 || value == values[next]) return {next, next, 0};
    size_t previous = next - 1;
    return {previous, next, (value - values[previous]) / (values[next] - values[previous])};
}

} // namespace crt::tracer
