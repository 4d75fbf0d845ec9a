// Affine transforms built from the `<translate, rotate, scale>` modifiers of spec §5.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "scene/scene_desc.hpp"

#include <vector>

namespace crt::tracer {

/// p ↦ linear·p + offset, with the inverse kept alongside (both are needed per ray).
class Transform {
public:
    Transform() = default;
    Transform(const glm::dmat3& linear, const Vec3& offset);

    /// The transform of a modifier list, applied left to right about the world origin.
    static Transform fromModifiers(const std::vector<scene::Modifier>& modifiers);

    bool isIdentity() const { return identity_; }
    /// this after `inner`: first inner, then this.
    Transform compose(const Transform& inner) const;
    Transform inverse() const;

    Vec3 point(const Vec3& p) const { return linear_ * p + offset_; }
    Vec3 vector(const Vec3& v) const { return linear_ * v; }
    /// A normal stays perpendicular to the surface under non-uniform scale: the inverse transpose.
    Vec3 normal(const Vec3& n) const { return glm::normalize(normalMatrix_ * n); }
    /// How much the transform scales the area of a surface element of unit normal n:
    /// |det L| · |L⁻ᵀ n| (the cofactor matrix maps the element's area vector).
    double areaScale(const Vec3& n) const {
        return std::abs(glm::determinant(linear_)) * glm::length(normalMatrix_ * n);
    }
    Ray ray(const Ray& r) const { return {point(r.origin), vector(r.dir), r.time}; }

    /// Bound of the rounding error of point(p), given p's own error bound (pbrt's
    /// "Transformations" error analysis).
    Vec3 pointError(const Vec3& p, const Vec3& pError) const;

    const glm::dmat3& linear() const { return linear_; }
    const Vec3& offset() const { return offset_; }

private:
    glm::dmat3 linear_{1.0};
    Vec3 offset_{0.0};
    glm::dmat3 normalMatrix_{1.0};
    bool identity_ = true;
};

/// A transform from object to world space with its inverse, as a scene keeps them.
struct TransformPair {
    Transform toWorld;
    Transform toObject;
};

} // namespace crt::tracer
