// Finds and loads the OpenImageIO module crt_image_io_oiio.so, at most once per process.
#pragma once

#include "tracer/image_io/module_abi.hpp"

#include <string>

namespace crt::tracer::image_io::detail {

/// Loads the module on the first call (other threads calling meanwhile wait for it) and returns
/// its table, or null with the reason in `error`. The outcome, success or failure, is final.
const CrtImageIoModule* loadedModule(std::string& error);

} // namespace crt::tracer::image_io::detail
