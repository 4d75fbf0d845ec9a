// A line prepared for the four-triangle test of triangle_quad.hpp.
#include "tracer/geometry/triangle_quad.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

QuadRay::QuadRay(const Ray& ray, const QuadFrame& frame) {
    const Vec3 local = ray.origin - frame.centre;
    double sum = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const auto o = static_cast<float>(local[axis]);
        const auto d = static_cast<float>(ray.dir[axis]);
        origin[axis] = Float4{o, o, o, o};
        dir[axis] = Float4{d, d, d, d};
        sum += std::abs(ray.dir[axis]);
    }
    dirSum = static_cast<float>(sum);
    // A corner and the origin are each rounded to float once (by at most 2⁻²⁴ of their
    // distance from the centre), and their difference once more (of at most the sum):
    // 2·2⁻²⁴ of the two distances, taken 3 times.
    const double originRadius = std::max({std::abs(local.x), std::abs(local.y), std::abs(local.z)});
    inputError = static_cast<float>(3 * 0x1p-24 * (frame.radius + originRadius));
}

} // namespace crt::tracer
