// Axis-aligned bounding boxes.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <algorithm>

namespace crt::tracer {

struct Bounds3 {
    Vec3 lo{kInfinity};
    Vec3 hi{-kInfinity};

    static Bounds3 everything() { return {Vec3(-kInfinity), Vec3(kInfinity)}; }
    static Bounds3 of(const Vec3& a, const Vec3& b) { return {glm::min(a, b), glm::max(a, b)}; }

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool finite() const {
        return std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) && std::isfinite(hi.x) &&
               std::isfinite(hi.y) && std::isfinite(hi.z);
    }
    Vec3 centroid() const { return 0.5 * (lo + hi); }
    Vec3 extent() const { return hi - lo; }
    double surfaceArea() const {
        Vec3 e = glm::max(extent(), Vec3(0.0));
        return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    void include(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void include(const Bounds3& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }
};

inline Bounds3 unionOf(Bounds3 a, const Bounds3& b) {
    a.include(b);
    return a;
}

} // namespace crt::tracer
