// OpenEXR output written with the OpenEXR library, instead of through the OpenImageIO module.
//
// EXR is the usual output of path-traced renders, and loading OpenImageIO's 260 libraries
// takes a third of a second or more, longer than tracing a small image. OpenEXR's own few
// libraries load in milliseconds. Reading still goes through the module.
#pragma once

#include "tracer/image_io/module_abi.hpp"

namespace crt::tracer::image_io {

/// The writing half of a module table (openImage, writeRows, closeImage) for the format
/// "openexr"; its other entries are null. Rows are 32-bit floats, 1 (the channel Y), 3 (R, G,
/// B) or 4 (R, G, B, A; the host premultiplies) per pixel, written in scan lines with ZIP
/// compression as they come.
const CrtImageIoModule& builtinExrWriter();

} // namespace crt::tracer::image_io
