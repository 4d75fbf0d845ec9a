// Camera rays; the coordinate system is left-handed (x right, y up, z into the screen).
#include "tracer/camera.hpp"

#include "tracer/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Camera::Camera(const scene::CameraDesc& desc, int width, int height, int dofSamples)
    : position_(desc.position), tanHalfFov_(std::tan(desc.fov * kPi / 360.0)),
      aspect_(static_cast<double>(width) / height), halfFov_(desc.fov * kPi / 360.0), width_(width), height_(height),
      projection_(desc.projection), shape_(desc.apertureShape), blades_(desc.apertureBlades),
      lensRadius_(desc.aperture / 1000.0), focalDistance_(desc.focalDistance),
      usesLens_(desc.aperture > 0 && dofSamples > 1) {
    forward_ = glm::normalize(desc.pointing - desc.position);
    halfViewHeight_ = desc.width > 0 ? desc.width / 2 / aspect_
                                     : glm::length(desc.pointing - desc.position) * tanHalfFov_;
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

bool Camera::sees(double u, double v) const {
    if (projection_ != scene::Projection::Fisheye) return true;
    const double x = (2 * u / width_ - 1) * aspect_, y = 1 - 2 * v / height_;
    return x * x + y * y <= 1;
}

Ray Camera::ray(double u, double v) const {
    // The image point from the middle: x across, y up, both from -1 to 1.
    const double x = 2 * u / width_ - 1, y = 1 - 2 * v / height_;
    switch (projection_) {
    case scene::Projection::Pinhole: break;
    case scene::Projection::Spherical: {
        const double longitude = x * kPi, latitude = y * (kPi / 2);
        Vec3 d = std::cos(latitude) * (std::sin(longitude) * right_ + std::cos(longitude) * forward_) +
                 std::sin(latitude) * up_;
        return {position_, glm::normalize(d)};
    }
    case scene::Projection::Orthographic:
        return {position_ + (x * halfViewHeight_ * aspect_) * right_ + (y * halfViewHeight_) * up_, forward_};
    case scene::Projection::Fisheye: {
        // Equidistant: the angle from the view direction grows with the distance from the
        // middle, fov/2 at the circle, whose diameter is the image's height.
        const double across = x * aspect_, radius = std::sqrt(across * across + y * y);
        const double theta = std::min(radius, 1.0) * halfFov_;
        const Vec3 around = radius > 0 ? (across / radius) * right_ + (y / radius) * up_ : right_;
        return {position_, glm::normalize(std::sin(theta) * around + std::cos(theta) * forward_)};
    }
    case scene::Projection::Cylindrical: {
        // The angle around `up` across the image, heights straight up, pixels square at the
        // middle.
        const double angle = x * halfFov_, height = y * halfFov_ / aspect_;
        return {position_, glm::normalize(std::sin(angle) * right_ + height * up_ + std::cos(angle) * forward_)};
    }
    }
    Vec3 d = forward_ + x * tanHalfFov_ * aspect_ * right_ + y * tanHalfFov_ * up_;
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
    Vec3 origin = pinhole.origin + p.x * right_ + p.y * up_;
    return {origin, glm::normalize(focus - origin)};
}

} // namespace crt::tracer
