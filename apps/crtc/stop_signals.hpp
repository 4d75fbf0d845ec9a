// What crtc does when a signal stops it (Ctrl-C, SIGTERM, SIGHUP, SIGQUIT).
#pragma once

#include <string>

namespace crt::crtc {

/// Installs handlers of SIGINT, SIGTERM, SIGHUP and SIGQUIT that remove every temporary
/// output file, print the current stop note, and end crtc as the signal's default action
/// would (so that a shell sees status 128 + the signal's number).
void installStopHandlers();

/// Makes exit() in the middle of writing an image (libjpeg's way of failing, on a full disk)
/// remove the temporary file and end crtc with status 2.
void installExitCleanup();

/// The line the handlers print, such as "crtc: interrupted; no image written": set before
/// an output is started, and again after each numbered frame is written.
void setStopNote(const std::string& line);

} // namespace crt::crtc
