// The centre and axis that spherical and cylindrical image mappings wrap around.
#pragma once

#include "tracer/geometry/ray.hpp"

namespace crt::tracer {

/// In object space: a sphere's or a torus's centre, a cylinder's or a cone's base, and the
/// shape's axis; the origin and +y for shapes without either. An image mapped about it stays
/// on the shape wherever the shape's own attributes put it.
struct MappingAxis {
    Vec3 origin{0.0};
    Vec3 axis{0, 1, 0}; ///< unit length

    /// `p` in the axis's own space: the origin at `origin`, +y along `axis`, turned by the
    /// least rotation that takes the axis to +y (so an upright shape is only moved).
    Vec3 toAxisSpace(const Vec3& p) const;
};

} // namespace crt::tracer
