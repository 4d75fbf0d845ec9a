// PNG output through libpng: a streamed writer behind the module table's writing entries.
#include "tracer/image_io/png_writer.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <new>

namespace crt::tracer::image_io {
namespace {

// Compressed bytes are collected up to this size, then written as one IDAT chunk.
constexpr std::size_t kChunkBytes = 1 << 16;
// The PNG specification's gAMA value for sRGB: 1/2.2 in units of 1e-5.
constexpr png_fixed_point kSrgbGamma = 45455;

// libpng reports an error by calling onError, which longjmps back to the setjmp of the
// function that called into libpng. Such a jump must skip no C++ destructor, so everything it
// can cross is plain data: this struct, the functions that call setjmp (each holding only
// scalars) and the callbacks. It is freed by destroyPng, not by a destructor.
struct PngFile {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    int height = 0;
    int nextRow = 0;
    std::size_t rowBytes = 0;
    char message[256] = {}; ///< why the write failed, kept by the first error
};

void keepMessage(PngFile& file, const char* what, const char* why) {
    if (file.message[0] == '\0')
        std::snprintf(file.message, sizeof file.message, "%s%s%s", what, why ? ": " : "",
                      why ? why : "");
}

void onError(png_structp png, png_const_charp message) {
    keepMessage(*static_cast<PngFile*>(png_get_error_ptr(png)), message, nullptr);
    png_longjmp(png, 1);
}

// Warnings concern unusual but valid input; none stops the write, and none is printed.
void onWarning(png_structp, png_const_charp) {}

// Through stdio rather than png_init_io, so that a failure carries errno's reason.
void onWrite(png_structp png, png_bytep data, std::size_t size) {
    PngFile& file = *static_cast<PngFile*>(png_get_io_ptr(png));
    if (std::fwrite(data, 1, size, file.file) != size) {
        keepMessage(file, "cannot write the file", std::strerror(errno));
        png_error(png, file.message);
    }
}

void onFlush(png_structp png) {
    PngFile& file = *static_cast<PngFile*>(png_get_io_ptr(png));
    if (std::fflush(file.file) != 0) {
        keepMessage(file, "cannot write the file", std::strerror(errno));
        png_error(png, file.message);
    }
}

void destroyPng(PngFile* file) {
    if (file->png) png_destroy_write_struct(&file->png, &file->info);
    if (file->file) std::fclose(file->file);
    delete file;
}

// Writes the header chunks; false (with the reason in file.message) if libpng failed.
bool writeHeader(PngFile& file, int width, int channels, bool srgb, int compression) {
    if (setjmp(png_jmpbuf(file.png))) return false;
    png_set_write_fn(file.png, &file, onWrite, onFlush);
    // libpng's default limit of a million pixels a side is meant for reading untrusted files;
    // for writing, the format's own limit applies.
    png_set_user_limits(file.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    const int colorType = channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : channels == 3 ? PNG_COLOR_TYPE_RGB
                                           : PNG_COLOR_TYPE_RGB_ALPHA;
    png_set_IHDR(file.png, file.info, png_uint_32(width), png_uint_32(file.height), 8, colorType,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // "Sub" alone: on rendered images it compresses better than libpng's default, a per-row
    // guess among all five filters, and saves the guessing.
    png_set_filter(file.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_level(file.png, compression);
    // Data chunks of 64 KiB rather than libpng's 8 KiB: fewer chunk headers and deflate calls.
    png_set_compression_buffer_size(file.png, kChunkBytes);
    if (srgb) {
        png_set_sRGB(file.png, file.info, PNG_sRGB_INTENT_PERCEPTUAL);
        png_set_gAMA_fixed(file.png, file.info, kSrgbGamma);
    }
    png_write_info(file.png, file.info);
    return true;
}

// Writes `count` rows of codes; false (with the reason in file.message) if libpng failed.
bool writeCodeRows(PngFile& file, const unsigned char* codes, int count) {
    if (setjmp(png_jmpbuf(file.png))) return false;
    for (int row = 0; row < count; ++row) png_write_row(file.png, codes + row * file.rowBytes);
    return true;
}

// Writes the end of the image data and the IEND chunk; false if libpng failed.
bool writeEnd(PngFile& file) {
    if (setjmp(png_jmpbuf(file.png))) return false;
    png_write_end(file.png, nullptr);
    return true;
}

void* openPng(const char* path, const char* format, int width, int height, int channels,
              int isFloat, int srgb, int compression, CrtImageErrorFn error, void* context) {
    if (std::strcmp(format, "png") != 0 || isFloat ||
        (channels != 1 && channels != 3 && channels != 4)) {
        error(context, "the built-in PNG writer stores 8-bit grey, RGB or RGBA images only");
        return nullptr;
    }
    auto* file = new (std::nothrow) PngFile;
    if (!file) {
        error(context, "out of memory");
        return nullptr;
    }
    file->height = height;
    file->rowBytes = std::size_t(width) * std::size_t(channels);
    file->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, file, onError, onWarning);
    file->info = file->png ? png_create_info_struct(file->png) : nullptr;
    if (!file->info) {
        error(context, "cannot start libpng (out of memory?)");
    } else if (file->file = std::fopen(path, "wb"); !file->file) {
        keepMessage(*file, "cannot create the file", std::strerror(errno));
        error(context, file->message);
    } else if (!writeHeader(*file, width, channels, srgb != 0, compression)) {
        error(context, file->message);
    } else {
        return file;
    }
    destroyPng(file);
    return nullptr;
}

int writePngRows(void* image, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error,
                 void* context) {
    PngFile& file = *static_cast<PngFile*>(image);
    if (file.message[0] != '\0') {
        error(context, file.message); // libpng's state after an error must not be used again
        return 0;
    }
    if (yBegin != file.nextRow || yEnd <= yBegin || yEnd > file.height) {
        error(context, "rows out of order");
        return 0;
    }
    if (!writeCodeRows(file, static_cast<const unsigned char*>(pixels), yEnd - yBegin)) {
        error(context, file.message);
        return 0;
    }
    file.nextRow = yEnd;
    return 1;
}

int closePng(void* image, int abandon, CrtImageErrorFn error, void* context) {
    PngFile* file = static_cast<PngFile*>(image);
    bool ok = true;
    if (!abandon) {
        if (file->message[0] != '\0') {
            ok = false; // an earlier write failed
        } else if (file->nextRow != file->height) {
            keepMessage(*file, "the image is incomplete", nullptr);
            ok = false;
        } else if (!writeEnd(*file)) {
            ok = false;
        } else {
            // Closed here, not in destroyPng, because a full disk may show only now.
            std::FILE* stream = file->file;
            file->file = nullptr;
            if (std::fclose(stream) != 0) {
                keepMessage(*file, "cannot write the file", std::strerror(errno));
                ok = false;
            }
        }
        if (!ok) error(context, file->message);
    }
    destroyPng(file);
    return ok ? 1 : 0;
}

const CrtImageIoModule kPngWriter = {
    kCrtImageIoAbiVersion, nullptr, openPng, writePngRows, closePng, nullptr, nullptr,
};

} // namespace

const CrtImageIoModule& builtinPngWriter() {
    return kPngWriter;
}

} // namespace crt::tracer::image_io
