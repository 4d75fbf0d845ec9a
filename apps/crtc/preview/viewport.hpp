// The preview's side views (docs/preview.md): the scene from the top, the front or the side,
// orthographic and in draft, to place the camera in.
#pragma once

#include "scene/scene_desc.hpp"

#include <optional>
#include <string_view>

namespace crt::crtc::preview {

/// Where a side view looks from: above (looking down −y, +x right, +z up the image), the
/// front (along +z, +x right, +y up) or the right side (along −x, +z right, +y up).
enum class ViewportAxis { Top, Front, Side };
std::optional<ViewportAxis> viewportAxis(std::string_view name);

/// A side view: the scene point at its middle in its own axes (the top view's x and z, the
/// front view's x and y, the side view's z and y), how many scene units it spans across,
/// and its size in pixels.
struct Viewport {
    ViewportAxis axis = ViewportAxis::Top;
    double across = 0, up = 0;
    double width = 10;
    int pixels = 240, lines = 180;
};
inline constexpr int kMostViewportPixels = 1024; ///< across and down

/// The scene as the view sees it: an orthographic camera far out along the view's axis
/// looking back, at the view's size, with one sample a pixel, no depth of field, one shadow
/// and glossy ray, under the Whitted integrator and with the shutter closed.
scene::SceneDesc viewportScene(const scene::SceneDesc& scene, const Viewport& view);

} // namespace crt::crtc::preview
