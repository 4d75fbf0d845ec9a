// Affine transforms from modifiers; rotations as POV-Ray (left-handed, x then y then z).
#include "tracer/transform.hpp"

namespace crt::tracer {

namespace {

glm::dmat3 rotationAbout(int axis, double degrees) {
    double radians = degrees * kPi / 180.0;
    double c = std::cos(radians), s = std::sin(radians);
    // Exact values for multiples of 90 degrees keep axis-aligned scenes axis-aligned.
    if (std::fmod(degrees, 90.0) == 0.0) {
        c = std::round(c);
        s = std::round(s);
    }
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    glm::dmat3 m(1.0); // glm is column-major: m[column][row]
    m[a][a] = c;
    m[b][a] = -s;
    m[a][b] = s;
    m[b][b] = c;
    return m;
}

} // namespace

Transform::Transform(const glm::dmat3& linear, const Vec3& offset)
    : linear_(linear), offset_(offset), normalMatrix_(glm::transpose(glm::inverse(linear))),
      identity_(linear == glm::dmat3(1.0) && offset == Vec3(0.0)) {}

Transform Transform::fromModifiers(const std::vector<scene::Modifier>& modifiers) {
    Transform result;
    for (const scene::Modifier& m : modifiers) {
        Transform step;
        switch (m.kind) {
        case scene::ModifierKind::Translate: step = Transform(glm::dmat3(1.0), m.value); break;
        case scene::ModifierKind::Scale:
            step = Transform(glm::dmat3(glm::dvec3(m.value.x, 0, 0), glm::dvec3(0, m.value.y, 0),
                                        glm::dvec3(0, 0, m.value.z)),
                             Vec3(0.0));
            break;
        case scene::ModifierKind::Rotate: {
            glm::dmat3 r = rotationAbout(2, m.value.z) * rotationAbout(1, m.value.y) * rotationAbout(0, m.value.x);
            step = Transform(r, Vec3(0.0));
            break;
        }
        case scene::ModifierKind::Matrix: step = Transform(m.linear, m.value); break;
        }
        result = step.compose(result);
    }
    return result;
}

Transform Transform::compose(const Transform& inner) const {
    if (inner.identity_) return *this;
    if (identity_) return inner;
    return Transform(linear_ * inner.linear_, linear_ * inner.offset_ + offset_);
}

Transform Transform::inverse() const {
    if (identity_) return *this;
    glm::dmat3 inv = glm::inverse(linear_);
    return Transform(inv, -(inv * offset_));
}

Vec3 Transform::pointError(const Vec3& p, const Vec3& pError) const {
    if (identity_) return pError;
    glm::dmat3 absLinear;
    for (int c = 0; c < 3; ++c) absLinear[c] = absolute(linear_[c]);
    Vec3 fromRounding = errorGamma(3) * (absLinear * absolute(p) + absolute(offset_));
    return (1 + errorGamma(3)) * (absLinear * pError) + fromRounding;
}

} // namespace crt::tracer
