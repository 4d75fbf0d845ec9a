// Axis-aligned bounding boxes.
#pragma once

#include "tracer/geometry/ray.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

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

/// Where the whole line o + t·d (t over all reals) is inside the box from lo to hi, and by
/// which faces it enters and leaves (2·axis, plus 1 for the `hi` side).
struct LineSpan {
    double enter = -kInfinity, exit = kInfinity;
    uint32_t enterFace = 0, exitFace = 0;
};

/// The slab test over the whole line; false when the line misses the box (a line parallel to a
/// slab is in the closed slab or misses it entirely).
inline bool lineSpan(const Ray& ray, const Vec3& lo, const Vec3& hi, LineSpan& span) {
    span = {};
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.dir[axis];
        if (d == 0) {
            if (o < lo[axis] || o > hi[axis]) return false;
            continue;
        }
        double tLo = (lo[axis] - o) / d, tHi = (hi[axis] - o) / d;
        auto faceLo = uint32_t(2 * axis), faceHi = uint32_t(2 * axis + 1);
        if (tLo > tHi) {
            std::swap(tLo, tHi);
            std::swap(faceLo, faceHi);
        }
        if (tLo > span.enter) {
            span.enter = tLo;
            span.enterFace = faceLo;
        }
        if (tHi < span.exit) {
            span.exit = tHi;
            span.exitFace = faceHi;
        }
    }
    return span.enter <= span.exit && std::isfinite(span.enter) && std::isfinite(span.exit);
}

inline Bounds3 unionOf(Bounds3 a, const Bounds3& b) {
    a.include(b);
    return a;
}

} // namespace crt::tracer
