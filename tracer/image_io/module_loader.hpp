// Finds and loads the OpenImageIO module crt_image_io_oiio.so, at most once per process.
#pragma once

#include "tracer/image_io/module_abi.hpp"

#include <string>

namespace crt::tracer::image_io::detail {

/// Starts loading on a background thread unless a load was already started; returns at once.
void startModuleLoad();

/// Waits for a load that was started, if any, and says whether there was one.
bool waitForStartedLoad();

/// Waits for the load (starting it on this thread if nobody has) and returns the module's
/// table, or null with the reason in `error`. The outcome, success or failure, is final.
const CrtImageIoModule* loadedModule(std::string& error);

} // namespace crt::tracer::image_io::detail
