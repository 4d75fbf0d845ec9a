// A line prepared for the four-triangle test of triangle_quad.hpp.
#include "tracer/geometry/triangle_quad.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

QuadRay::QuadRay(const Ray& ray, const QuadFrame& frame) {
    // The origin moved along the line to its point nearest the frame's centre: the edge
    // functions are the same from any point of the line, and their rounding grows with the
    // origin's distance from the triangles, which from a far camera would swamp them.
    const Vec3 fromCentre = ray.origin - frame.centre;
    const double along = glm::dot(ray.dir, ray.dir);
    const double t = along > 0 ? -glm::dot(fromCentre, ray.dir) / along : 0;
    const Vec3 step = std::isfinite(t) ? t * ray.dir : Vec3(0.0);
    const Vec3 local = fromCentre + step;
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
    // 2·2⁻²⁴ of the two distances, taken 3 times. Moving the origin rounds in double, relative
    // to the distances it adds up.
    auto largest = [](const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); };
    inputError = static_cast<float>(3 * 0x1p-24 * (frame.radius + largest(local)) +
                                    0x1p-50 * (largest(fromCentre) + largest(step)));
}

} // namespace crt::tracer
