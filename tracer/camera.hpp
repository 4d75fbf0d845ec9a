// The camera of spec §5-§6: pinhole, spherical, orthographic, fisheye or cylindrical
// projection, optional thin lens for depth of field.
#pragma once

#include "tracer/geometry/ray.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

class Camera {
public:
    Camera(const scene::CameraDesc& desc, int width, int height, int dofSamples);

    /// Whether depth of field is on: aperture > 0 and more than one DOF sample (as the original).
    bool usesLens() const { return usesLens_; }
    /// Whether the image point (u, v) has a ray: all do but those outside a fisheye's circle,
    /// which stay black (and transparent).
    bool sees(double u, double v) const;
    /// The pinhole ray through the continuous image point (u, v), in pixels from the top left.
    Ray ray(double u, double v) const;
    /// The ray from the lens point chosen by `lensSample` (in [0,1)²), aimed at where the
    /// pinhole ray meets the focal plane.
    Ray lensRay(double u, double v, const Vec2& lensSample) const;
    /// A point of the aperture shape with circumradius 1, in (right, up) coordinates.
    Vec2 aperturePoint(const Vec2& sample) const;

    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }

private:
    Vec3 position_, forward_, right_, up_;
    double tanHalfFov_, aspect_;
    double halfFov_;            ///< radians
    double halfViewHeight_ = 0; ///< orthographic: half the view's height, in scene units
    double width_, height_;
    scene::Projection projection_;
    scene::ApertureShape shape_;
    int blades_;
    double lensRadius_, focalDistance_;
    bool usesLens_;
};

} // namespace crt::tracer
