// Where crtc finds the files it keeps beside itself: the MPI module and the preview program.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace crt::crtc {

/// The places a file of crtc's named `fileName` may be, in the order to try them: beside the
/// running executable (the build tree puts it there), then <executable's folder>/../lib/crt/
/// (an installed layout). Empty when the executable's folder is unknown.
std::vector<std::filesystem::path> companionCandidates(const std::string& fileName);

/// "A and B" for an error message that says where `fileName` was looked for.
std::string describeCandidates(const std::vector<std::filesystem::path>& candidates);

} // namespace crt::crtc
