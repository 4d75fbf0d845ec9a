// The preview's camera as CRT source: a `Camera { ... }` literal, and that literal written
// into the `camera ->` attribute of a script's Settings block.
#pragma once

#include "interpreter.hpp"
#include "scene/scene_desc.hpp"

#include <string>

namespace crt::crtc::preview {

/// The camera as a formatted `Camera { ... }` literal: position, pointing and fov always,
/// the other attributes where they differ from their defaults. With `multiline`, one
/// attribute a line (indented by the formatter once in a script).
std::string cameraLiteral(const scene::CameraDesc& camera, bool multiline = false);

/// The outcome of placing a camera into a script.
struct CameraEdit {
    bool ok = false;
    std::string text;    ///< the new script, when ok
    std::string message; ///< what was done, or why nothing was (where to paste instead)
};

/// Replaces the `camera -> Camera { ... }` value of the script's Settings block with
/// `camera` (or adds a camera attribute to a Settings block without one), and re-indents
/// the lines changed with the formatter. A camera given by a name or a macro call is left
/// alone: the message says where it is set, for the user to paste the literal there.
CameraEdit placeCamera(const std::string& path, const std::string& text, const scene::CameraDesc& camera,
                       const lang::EvalOptions& options);

/// Writes `text` to `path` through a temporary file beside it and a rename, so that the
/// script is never seen half written; false, with `error` set, if that fails.
bool replaceFile(const std::string& path, const std::string& text, std::string& error);

} // namespace crt::crtc::preview
