// What a ray that leaves the scene sees: a color, a sky gradient, a panorama or layers of
// patterns (spec §5).
#pragma once

#include "tracer/image.hpp"
#include "tracer/texture.hpp"
#include "scene/scene_desc.hpp"

#include <vector>

namespace crt::tracer {

class Background {
public:
    /// `panorama` is the decoded image of an image background (null otherwise).
    Background(const scene::BackgroundDesc& desc, const Image* panorama);
    /// The color seen along the unit direction d.
    Vec3 radiance(const Vec3& d) const;

    /// The panorama of an image background that has one, else null.
    const Image* panorama() const {
        return kind_ == scene::BackgroundKind::Image && panorama_ && panorama_->width > 0 ? panorama_ : nullptr;
    }
    /// Where the panorama is read for direction d: u across, v down, both in [0, 1].
    Vec2 panoramaCoordinates(const Vec3& d) const;
    /// The unit direction read at (u, v): panoramaCoordinates' inverse.
    Vec3 panoramaDirection(const Vec2& uv) const;

private:
    /// The pattern layers' colour along d.
    Vec3 layered(const Vec3& d) const;

    scene::BackgroundKind kind_;
    Vec3 color_, horizon_, sky_;
    const Image* panorama_;
    double angle_;
    std::vector<Texture> layers_; ///< bottom first
};

} // namespace crt::tracer
