// crtc --preview: a live preview of the script in the browser, re-rendered when the script
// is saved, with a mouse-driven camera (docs/preview.md).
#pragma once

#include "options.hpp"

namespace crt::crtc {

/// Serves the preview until Ctrl-C, SIGTERM or the page's quit; returns crtc's exit status
/// (0, or 2 when the server cannot start).
int previewCommand(const Options& options);

} // namespace crt::crtc
