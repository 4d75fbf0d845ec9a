// Checks of an image file's header made before OpenImageIO opens it: the lengths and sizes
// that OpenImageIO's readers (or the libraries under them) would trust and reserve memory for.
// Part of the OpenImageIO module, without OpenImageIO itself.
#pragma once

#include "tracer/image_io/module_abi.hpp"

#include <string>

namespace crt::tracer::image_io {

/// The host's limit on the size of an image, asked before anything is reserved for one.
struct SizeCheck {
    CrtImageSizeFn accepts;
    void* context;
    bool operator()(long long width, long long height, int channels = 0) const {
        return accepts(context, width, height, channels) != 0;
    }
};

/// What the module fails with when the host refused a size: the host reports its own reason.
inline constexpr const char* kSizeRefused = "the image is larger than allowed";

/// Why `path` must not be opened, told by its bytes before OpenImageIO opens it, or empty
/// (also when the file cannot be read: OpenImageIO then says why).
std::string refusedBeforeOpen(const char* path, const SizeCheck& accepts);

} // namespace crt::tracer::image_io
