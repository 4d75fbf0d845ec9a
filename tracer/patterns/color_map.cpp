// Colour maps, looked up as POV-Ray's blend maps are.
#include "tracer/patterns/color_map.hpp"

#include "tracer/patterns/map_position.hpp"

namespace crt::tracer {

ColorMap::ColorMap(const std::vector<scene::ColorStop>& stops) {
    for (const scene::ColorStop& stop : stops) {
        values_.push_back(stop.value);
        colors_.push_back({stop.color.r, stop.color.g, stop.color.b, stop.color.a});
    }
    if (colors_.empty()) {
        values_.push_back(0);
        colors_.push_back({0, 0, 0, 1});
    }
}

Vec4 ColorMap::at(double value) const {
    MapPosition at = mapPosition(values_, value);
    if (at.below == at.above) return colors_[at.below];
    return colors_[at.below] + (colors_[at.above] - colors_[at.below]) * at.fraction;
}

bool ColorMap::translucent() const {
    for (const Vec4& c : colors_)
        if (c.a != 1) return true;
    return false;
}

} // namespace crt::tracer
