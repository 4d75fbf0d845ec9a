// PNG output written with libpng, instead of through the OpenImageIO module.
//
// PNG is the usual output, and loading OpenImageIO's 260 libraries can cost more than
// tracing a small image, while a PNG needs nothing of it. Other formats still go through the
// module, and so does reading.
#pragma once

#include "tracer/image_io/module_abi.hpp"

namespace crt::tracer::image_io {

/// The writing half of a module table (openImage, writeRows, closeImage) for the format "png";
/// its other entries are null. Rows are 8-bit codes, 1 (grey), 3 (RGB) or 4 (RGBA, straight
/// alpha) per pixel, written to the file as they come; `pngCompression` is zlib's level.
/// `srgb` adds the sRGB chunk (with the gAMA chunk the PNG specification pairs with it).
const CrtImageIoModule& builtinPngWriter();

} // namespace crt::tracer::image_io
