// PNG output written here, on zlib, instead of through the OpenImageIO module.
//
// PNG is crtc's default output. Loading OpenImageIO's 260 libraries takes 0.2–0.3 s, longer
// than tracing an 800×600 image, and a PNG needs nothing of it: a signature, a header chunk,
// the filtered rows deflated into data chunks, an end chunk. Other formats still go through
// the module, and so does reading.
#pragma once

#include "tracer/image_io/module_abi.hpp"

namespace crt::tracer::image_io {

/// The writing half of a module table (openImage, writeRows, closeImage) for the format "png";
/// its other entries are null. Rows are 8-bit codes, 1 (grey), 3 (RGB) or 4 (RGBA, straight
/// alpha) per pixel, each stored with PNG's "Sub" filter; `pngCompression` is zlib's level.
/// `srgb` adds the sRGB chunk (with the gAMA chunk the PNG specification pairs with it).
const CrtImageIoModule& builtinPngWriter();

} // namespace crt::tracer::image_io
