// The delay of each frame of an animated GIF: the format keeps it in hundredths of a second,
// so most frame rates (15 a second: 6⅔ hundredths) need delays that differ from frame to
// frame for the animation to keep its rate.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crt::tracer::image_io {

/// The delays, in hundredths of a second, of `frames` frames at `fps` frames a second: frame
/// i ends at the hundredth nearest to (i + 1) / fps seconds, and each delay is at least 1.
std::vector<std::uint16_t> gifFrameDelays(int frames, double fps);

/// The delay of each frame of the GIF file at `path` (from its graphic control extensions);
/// nothing, with `error` set, when the file is not a GIF this can read.
std::optional<std::vector<std::uint16_t>> readGifDelays(const std::string& path,
                                                        std::string& error);

/// Sets the delays of the GIF file at `path`, which must have a graphic control extension
/// for each of its `delays.size()` frames; false, with `error` set, otherwise.
bool writeGifDelays(const std::string& path, const std::vector<std::uint16_t>& delays,
                    std::string& error);

} // namespace crt::tracer::image_io
