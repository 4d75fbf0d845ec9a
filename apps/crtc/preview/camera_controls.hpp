// The preview's mouse camera: orbit around the point looked at, pan, dolly and zoom, as
// changes of a scene camera (position, pointing, up, fov), never of the image.
#pragma once

#include "scene/scene_desc.hpp"

namespace crt::crtc::preview {

/// Turns the camera around its pointing point: `yawDegrees` about the up vector (positive:
/// the camera moves to its right), `pitchDegrees` over it (positive: the camera rises). The distance to the
/// pointing point is kept, and the pitch stops a degree short of the up vector so that the
/// view never flips over.
scene::CameraDesc orbit(scene::CameraDesc camera, double yawDegrees, double pitchDegrees);

/// Slides camera and pointing point together across the view so that the scene moves
/// `right` and `up` on the image, in fractions of the view's height at the pointing
/// point's distance: a drag follows the mouse. The distance is kept.
scene::CameraDesc pan(scene::CameraDesc camera, double right, double up);

/// Moves the camera toward the pointing point (factor < 1) or away from it (> 1); the
/// distance never falls below a millionth of what it was nor below 1e-6.
scene::CameraDesc dolly(scene::CameraDesc camera, double factor);

/// The vertical field of view, kept within [1, 170] degrees.
scene::CameraDesc withFov(scene::CameraDesc camera, double fovDegrees);

} // namespace crt::crtc::preview
