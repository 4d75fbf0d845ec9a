// Encodes a preview frame as PNG bytes in memory, for the browser.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace crt::crtc::preview {

/// An 8-bit RGB image, row-major, top row first, as a PNG file's bytes. Compressed at zlib's
/// fastest level: the frame crosses a loopback connection, where time matters and size does not.
std::vector<std::uint8_t> encodePng(int width, int height, std::span<const std::uint8_t> rgb);

} // namespace crt::crtc::preview
