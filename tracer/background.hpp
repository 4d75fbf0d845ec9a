// What a ray that leaves the scene sees: a color, a sky gradient or a panorama (spec §5).
#pragma once

#include "tracer/image.hpp"
#include "scene/scene_desc.hpp"

namespace crt::tracer {

class Background {
public:
    /// `panorama` is the decoded image of an image background (null otherwise).
    Background(const scene::BackgroundDesc& desc, const Image* panorama);
    /// The color seen along the unit direction d.
    Vec3 radiance(const Vec3& d) const;

private:
    scene::BackgroundKind kind_;
    Vec3 color_, horizon_, sky_;
    const Image* panorama_;
    double angle_;
};

} // namespace crt::tracer
