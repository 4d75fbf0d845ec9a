// Camera rays; the coordinate system is left-handed (x right, y up, z into the screen).
#include "tracer/camera.hpp"

#include "tracer/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Camera::Camera(const scene::CameraDesc& desc, int width, int height, int dofSamples)
    : position_(desc.position), tanHalfFov_(std::tan(desc.fov * kPi / 360.0)),
      aspect_(static_cast<double>(width) / height), width_(width), height_(height),
      projection_(desc.projection), shape_(desc.apertureShape), blades_(desc.apertureBlades),
      lensRadius_(desc.aperture / 1000.0), focalDistance_(desc.focalDistance),
      usesLens_(desc.aperture > 0 && dofSamples > 1) {
    forward_ = glm::normalize(desc.pointing - desc.position);
    Vec3 up = desc.up;
    if (glm::length(glm::cross(up, forward_)) < 1e-12 * glm::length(up)) up = Vec3(0, 0, 1);
    // Left-handed: with y up and z forward, up × forward is +x.
    right_ = glm::normalize(glm::cross(up, forward_));
    up_ = glm::cross(forward_, right_);
    if (desc.roll != 0) {
        // A positive roll turns the picture's up towards its right (clockwise on screen).
        double a = desc.roll * kPi / 180.0, c = std::cos(a), s = std::sin(a);
        Vec3 r = c * right_ - s * up_;
        Vec3 u = s * right_ + c * up_;
        right_ = r;
        up_ = u;
    }
}

Ray Camera::ray(double u, double v) const {
    if (projection_ == scene::Projection::Spherical) {
        double longitude = (2 * u / width_ - 1) * kPi;
        double latitude = (1 - 2 * v / height_) * (kPi / 2);
        Vec3 d = std::cos(latitude) * (std::sin(longitude) * right_ + std::cos(longitude) * forward_) +
                 std::sin(latitude) * up_;
        return {position_, glm::normalize(d)};
    }
    Vec3 d = forward_ + (2 * u / width_ - 1) * tanHalfFov_ * aspect_ * right_ + (1 - 2 * v / height_) * tanHalfFov_ * up_;
    return {position_, glm::normalize(d)};
}

Vec2 Camera::aperturePoint(const Vec2& sample) const {
    switch (shape_) {
    case scene::ApertureShape::Circle: return concentricDisc(sample);
    case scene::ApertureShape::Line: return {2 * sample.x - 1, 0};
    case scene::ApertureShape::Gaussian: {
        // Box–Muller with σ = the radius (1 here).
        double r = std::sqrt(-2 * std::log(std::max(1 - sample.x, 1e-300)));
        double phi = 2 * kPi * sample.y;
        return {r * std::cos(phi), r * std::sin(phi)};
    }
    case scene::ApertureShape::Polygon: break;
    }
    // A regular polygon with a vertex on +right: pick a fan triangle by the first
    // coordinate, reuse its remainder, and sample the triangle uniformly.
    int n = std::max(blades_, 3);
    double scaled = sample.x * n;
    int k = std::min(static_cast<int>(scaled), n - 1);
    double a = scaled - k, b = sample.y;
    double su = std::sqrt(a);
    double w1 = su * (1 - b), w2 = su * b; // barycentric weights of the two outer vertices
    double angle1 = 2 * kPi * k / n, angle2 = 2 * kPi * (k + 1) / n;
    return {w1 * std::cos(angle1) + w2 * std::cos(angle2), w1 * std::sin(angle1) + w2 * std::sin(angle2)};
}

Ray Camera::lensRay(double u, double v, const Vec2& lensSample) const {
    Ray pinhole = ray(u, v);
    double along = glm::dot(pinhole.dir, forward_);
    if (along <= 0) return pinhole;
    Vec3 focus = pinhole.origin + pinhole.dir * (focalDistance_ / along);
    Vec2 p = aperturePoint(lensSample) * lensRadius_;
    Vec3 origin = position_ + p.x * right_ + p.y * up_;
    return {origin, glm::normalize(focus - origin)};
}

} // namespace crt::tracer
