// The C table through which crt_image_io calls the OpenImageIO module crt_image_io_oiio.so.
//
// Plain C types only: no exception, std::string or OpenImageIO type crosses the boundary,
// so the module and its host need not agree on anything but this header. Strings and
// buffers the module produces go back through the host's callbacks, so that memory is
// allocated and freed on one side.
#pragma once

#include <cstdint>

extern "C" {

/// Raised whenever a function's signature or meaning changes; the host refuses other versions.
inline constexpr int kCrtImageIoAbiVersion = 7;

/// The name of the module's one exported function.
inline constexpr const char* kCrtImageIoEntryName = "crt_image_io_module";

/// Whether the host takes an image of width × height pixels of `channels` values each (0 where
/// a header does not tell before the file is opened: at most four); when not, the host keeps
/// the reason and the call fails. The module asks it with the size a file's header claims,
/// before any pixel is read or room is made for one: where a reader would reserve memory for a
/// size while it opens the file, before OpenImageIO sees the file.
using CrtImageSizeFn = int (*)(void* context, long long width, long long height, int channels);

/// Returns room for width × height × channels floats (3: RGB; 4: RGB and alpha), or null when
/// out of memory.
using CrtImageAllocFn = float* (*)(void* context, int width, int height, int channels);

/// Receives the message of a failed call.
using CrtImageErrorFn = void (*)(void* context, const char* message);

/// What the module reports about a file (used by tests and tools, not by rendering).
struct CrtImageInfo {
    int width;
    int height;
    int channels;
    int subimages;
    int isInteger;
    int fpsNumerator; ///< 0 when the file has no frame rate
    int fpsDenominator;
    int loopCount; ///< -1 when the file does not say; 0 = forever
    char format[32];
};

/// The module's functions; each returns 1 on success, 0 after calling `error` once.
struct CrtImageIoModule {
    int abiVersion;
    /// Reads subimage 0 into 3 channels of floats (integer formats as value / max), or 4 when
    /// the file has an alpha channel, once `accepts` took its size.
    int (*readImage)(const char* path, int* isInteger, CrtImageSizeFn accepts, CrtImageAllocFn alloc,
                     CrtImageErrorFn error, void* context);
    /// Opens `path` for one image in the OpenImageIO format `format` ("png", "openexr" …),
    /// whatever the file name, to be written in bands of rows from the top; pixels will be
    /// `channels` uint8 values each, or floats when `isFloat`. `pngCompression` (0–9) is the
    /// zlib level of a PNG. Returns a handle for writeRows and closeImage, or null.
    void* (*openImage)(const char* path, const char* format, int width, int height, int channels,
                       int isFloat, int srgb, int pngCompression, CrtImageErrorFn error,
                       void* context);
    /// Writes rows [yBegin, yEnd), the next ones after those written before.
    int (*writeRows)(void* image, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error,
                     void* context);
    /// Completes the file (or, when `abandon`, only closes it) and frees the handle.
    int (*closeImage)(void* image, int abandon, CrtImageErrorFn error, void* context);
    /// Writes an animated GIF of `frameCount` frames of uint8 pixels, looping forever.
    int (*writeAnimatedGif)(const char* path, int width, int height, int channels, int frameCount,
                            const std::uint8_t* const* frames, int fpsNumerator, int fpsDenominator,
                            CrtImageErrorFn error, void* context);
    /// Fills `info` from the file's header, once `accepts` took its size.
    int (*describeImage)(const char* path, CrtImageInfo* info, CrtImageSizeFn accepts,
                         CrtImageErrorFn error, void* context);
};

/// The type of the module's exported entry point.
using CrtImageIoEntryFn = const CrtImageIoModule* (*)();

} // extern "C"
