// An image module for the render benchmark only: it stores the rendered pixels as raw bytes
// (no header, no compression) instead of an image file, and links nothing but the C
// library. run.sh points crtc at it (CRT_IMAGE_IO_MODULE) to measure the same renders
// without OpenImageIO, whose 260 libraries take longer to load than the tracing of a small
// render. Never installed and never used by crtc unless named.
#include "tracer/image_io/module_abi.hpp"

#include <cstdio>

namespace {

struct RawImage {
    std::FILE* file;
    long rowBytes;
};

int readImage(const char*, int*, CrtImageAllocFn, CrtImageErrorFn error, void* context) {
    error(context, "the benchmark's null image module reads no images");
    return 0;
}

void* openImage(const char* path, const char*, int width, int, int channels, int isFloat, int,
                int, CrtImageErrorFn error, void* context) {
    std::FILE* file = std::fopen(path, "wb");
    if (!file) {
        error(context, "cannot open the output file");
        return nullptr;
    }
    long sampleBytes = isFloat ? static_cast<long>(sizeof(float)) : 1;
    return new RawImage{file, static_cast<long>(width) * channels * sampleBytes};
}

int writeRows(void* handle, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error,
              void* context) {
    auto* image = static_cast<RawImage*>(handle);
    size_t bytes = static_cast<size_t>(image->rowBytes) * static_cast<size_t>(yEnd - yBegin);
    if (std::fwrite(pixels, 1, bytes, image->file) != bytes) {
        error(context, "cannot write the output file");
        return 0;
    }
    return 1;
}

int closeImage(void* handle, int, CrtImageErrorFn error, void* context) {
    auto* image = static_cast<RawImage*>(handle);
    bool ok = std::fclose(image->file) == 0;
    delete image;
    if (!ok) error(context, "cannot complete the output file");
    return ok ? 1 : 0;
}

int writeAnimatedGif(const char*, int, int, int, int, const std::uint8_t* const*, int, int,
                     CrtImageErrorFn error, void* context) {
    error(context, "the benchmark's null image module writes no animations");
    return 0;
}

int describeImage(const char*, CrtImageInfo*, CrtImageErrorFn error, void* context) {
    error(context, "the benchmark's null image module reads no images");
    return 0;
}

const CrtImageIoModule kModule{kCrtImageIoAbiVersion, readImage,        openImage,    writeRows,
                               closeImage,            writeAnimatedGif, describeImage};

} // namespace

extern "C" __attribute__((visibility("default"))) const CrtImageIoModule* crt_image_io_module() {
    return &kModule;
}
