// crtc's render mode: evaluates each frame, renders it and writes the image(s).
#pragma once

#include "options.hpp"

#include <functional>
#include <string>

namespace crt::crtc {

/// Evaluates one frame into a compilation, printing its diagnostics; returns false on errors.
using CompileFrame = std::function<bool(int frame, lang::Compilation& out)>;

/// Renders the selected frames and writes the output; returns crtc's exit status.
int renderCommand(const Options& options, const CompileFrame& compileFrame);

/// The default output path: the script's path with .png (.gif for an animation).
std::string defaultOutput(const std::string& script, bool animation);
/// Whether an output name has a printf-style frame number (%d, %04d …).
bool hasFramePattern(const std::string& output);
/// The output name with the frame number substituted for its pattern.
std::string numberedOutput(const std::string& output, int frame);

} // namespace crt::crtc
