#include "preview/viewport.hpp"

#include "preview/render_plan.hpp"

namespace crt::crtc::preview {

namespace {

/// How far out the camera stands: beyond anything a scene places (what is behind it is not
/// seen), and near enough that the rays' rounding stays far below a pixel.
constexpr double kDistance = 1e6;

} // namespace

std::optional<ViewportAxis> viewportAxis(std::string_view name) {
    if (name == "top") return ViewportAxis::Top;
    if (name == "front") return ViewportAxis::Front;
    if (name == "side") return ViewportAxis::Side;
    return std::nullopt;
}

scene::SceneDesc viewportScene(const scene::SceneDesc& scene, const Viewport& view) {
    scene::SceneDesc desc = passScene(scene, RenderPass{1, true});
    desc.settings.width = view.pixels;
    desc.settings.height = view.lines;
    desc.settings.integrator = scene::Integrator::Whitted;
    desc.settings.supersampling = 1;
    desc.settings.antialias = scene::Antialias::Grid;
    desc.settings.shutterOpen = desc.settings.shutterClose = 0;
    desc.motion = {};
    scene::CameraDesc camera;
    camera.projection = scene::Projection::Orthographic;
    camera.width = view.width;
    switch (view.axis) {
    case ViewportAxis::Top:
        camera.position = {view.across, kDistance, view.up};
        camera.pointing = {view.across, 0, view.up};
        camera.up = {0, 0, 1};
        break;
    case ViewportAxis::Front:
        camera.position = {view.across, view.up, -kDistance};
        camera.pointing = {view.across, view.up, 0};
        break;
    case ViewportAxis::Side:
        camera.position = {kDistance, view.up, view.across};
        camera.pointing = {0, view.up, view.across};
        break;
    }
    camera.focalDistance = kDistance;
    camera.source = scene.camera.source;
    desc.camera = camera;
    return desc;
}

} // namespace crt::crtc::preview
