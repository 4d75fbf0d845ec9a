// What the preview renders, pass by pass: a coarse image at once, then finer ones up to the
// quality the page asks for, and a quick one while the camera is being dragged.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/renderer.hpp"

#include <string_view>
#include <vector>

namespace crt::crtc::preview {

/// The page's quality switches; they change what is rendered, never the script.
struct ViewQuality {
    bool draft = false; ///< one sample a pixel, no depth of field, one shadow and glossy ray
    double scale = 1;   ///< of the script's image size, in [1/16, 1]
};

/// One render of the scene on the way to the final image.
struct RenderPass {
    double scale = 1;   ///< of the script's image size
    bool draft = true;  ///< reduced sampling (as ViewQuality::draft)
};

/// The passes that refine an image: 1/8 and 1/2 of the size in draft, the full size in draft,
/// then (unless the page asks for draft) the full size at the script's own quality.
std::vector<RenderPass> refinementPasses(const ViewQuality& quality);

/// The pass rendered for each move while the camera is dragged: `fraction` of the page's
/// size, in draft.
RenderPass interactivePass(const ViewQuality& quality, double fraction);

/// The fraction of the size for the drag's next frame, given the last one's and the seconds
/// it took: what keeps a drag at about 20 frames a second, between 1/8 and 1/2 (a pass's
/// time grows with its pixels, so with the square of the fraction).
double nextDragFraction(double fraction, double seconds);
inline constexpr double kFirstDragFraction = 0.5;

/// The scene as `pass` renders it: its image size scaled (at least 1×1), and with draft,
/// its sampling reduced.
scene::SceneDesc passScene(const scene::SceneDesc& scene, const RenderPass& pass);

/// The camera samples of a pass: one a pixel in draft, else the scene's own.
tracer::SampleBudget passBudget(const RenderPass& pass);

} // namespace crt::crtc::preview
