// How `crtc --preview` starts the preview program, crtc-preview.
#pragma once

namespace crt::crtc {

/// Replaces this process by crtc-preview (found as companion_files.hpp says) with crtc's own
/// arguments. Returns only when that fails, having said why: crtc's exit status, 2.
int launchPreview(char** argv);

} // namespace crt::crtc
