// Colour maps, looked up as POV-Ray's blend maps are.
#include "tracer/patterns/color_map.hpp"

#include "tracer/lights.hpp"

namespace crt::tracer {

ColorMap::ColorMap(const std::vector<scene::ColorStop>& stops) {
    for (const scene::ColorStop& stop : stops) {
        values_.push_back(stop.value);
        colors_.push_back(rgb(stop.color));
    }
    if (colors_.empty()) {
        values_.push_back(0);
        colors_.push_back(Vec3(0.0));
    }
}

Vec3 ColorMap::at(double value) const {
    size_t last = values_.size() - 1;
    if (!(value < values_[last])) return colors_[last]; // NaN too: the map's end
    size_t next = 0;
    while (value > values_[next]) ++next;
    if (next == 0 || value == values_[next]) return colors_[next];
    size_t previous = next - 1;
    double fraction = (value - values_[previous]) / (values_[next] - values_[previous]);
    return colors_[previous] + (colors_[next] - colors_[previous]) * fraction;
}

} // namespace crt::tracer
