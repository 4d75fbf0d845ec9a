// A colour map: the colour of each pattern value, linear between stops (POV-Ray's color_map).
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/ray.hpp"

#include <vector>

namespace crt::tracer {

class ColorMap {
  public:
    /// `stops` are non-decreasing in value (the front end checks); there is at least one.
    explicit ColorMap(const std::vector<scene::ColorStop>& stops);

    /// The colour and alpha at `value`: the first or last stop's outside them; where stops
    /// share a value, the colour changes there at once.
    Vec4 at(double value) const;
    /// The colour of stop `index` (the last one past the end): discrete patterns' colours.
    Vec4 entry(size_t index) const { return colors_[std::min(index, colors_.size() - 1)]; }
    /// Whether some stop's alpha is not 1 (the surface lets light through there).
    bool translucent() const;

  private:
    std::vector<double> values_;
    std::vector<Vec4> colors_;
};

} // namespace crt::tracer
