// PNG encoding on zlib (ISO/IEC 15948): chunks, the Sub filter, deflate, CRCs.
#include "tracer/image_io/png_writer.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace crt::tracer::image_io {
namespace {

// Deflated bytes are collected up to this size, then written as one IDAT chunk.
constexpr std::size_t kChunkBytes = 1 << 16;

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr unsigned char kFilterSub = 1;
// The PNG specification's gAMA value for sRGB: 1/2.2 in units of 1e-5.
constexpr unsigned kSrgbGamma = 45455;

struct PngFile {
    std::FILE* file = nullptr;
    z_stream zlib{};
    bool zlibReady = false;
    int width = 0, height = 0, channels = 3;
    int nextRow = 0;
    std::vector<unsigned char> filtered; ///< one row: the filter byte, then the filtered codes
    std::vector<unsigned char> deflated; ///< the data chunk being filled

    ~PngFile() {
        if (zlibReady) deflateEnd(&zlib);
        if (file) std::fclose(file);
    }
};

void putBigEndian32(unsigned char* at, unsigned value) {
    at[0] = static_cast<unsigned char>(value >> 24);
    at[1] = static_cast<unsigned char>(value >> 16);
    at[2] = static_cast<unsigned char>(value >> 8);
    at[3] = static_cast<unsigned char>(value);
}

std::string systemError(const char* what) {
    return std::string(what) + ": " + std::strerror(errno);
}

// A chunk is its length, its type, its data and the CRC of type and data.
bool writeChunk(std::FILE* file, const char (&type)[5], const unsigned char* data,
                std::size_t size) {
    unsigned char head[8];
    putBigEndian32(head, static_cast<unsigned>(size));
    std::memcpy(head + 4, type, 4);
    uLong crc = crc32(0L, head + 4, 4);
    if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));
    unsigned char tail[4];
    putBigEndian32(tail, static_cast<unsigned>(crc));
    return std::fwrite(head, 1, 8, file) == 8 &&
           (size == 0 || std::fwrite(data, 1, size, file) == size) &&
           std::fwrite(tail, 1, 4, file) == 4;
}

bool writeHeader(PngFile& png, bool srgb) {
    unsigned char header[13];
    putBigEndian32(header, static_cast<unsigned>(png.width));
    putBigEndian32(header + 4, static_cast<unsigned>(png.height));
    header[8] = 8;                                                 // bits per sample
    header[9] = png.channels == 1 ? 0 : png.channels == 3 ? 2 : 6; // grey, RGB, RGBA
    header[10] = 0;                                                // deflate
    header[11] = 0; // adaptive filtering, one filter byte a row
    header[12] = 0; // not interlaced
    if (std::fwrite(kSignature, 1, sizeof kSignature, png.file) != sizeof kSignature ||
        !writeChunk(png.file, "IHDR", header, sizeof header))
        return false;
    if (!srgb) return true;
    const unsigned char intent = 0; // perceptual
    unsigned char gamma[4];
    putBigEndian32(gamma, kSrgbGamma);
    return writeChunk(png.file, "sRGB", &intent, 1) && writeChunk(png.file, "gAMA", gamma, 4);
}

// Runs deflate with `flush` until it has taken all its input (and, for Z_FINISH, ended the
// stream), writing a data chunk each time the output fills.
bool deflateInto(PngFile& png, int flush, std::string& problem) {
    while (true) {
        const int status = deflate(&png.zlib, flush);
        if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
            problem = "compression failed";
            return false;
        }
        const std::size_t filled = kChunkBytes - png.zlib.avail_out;
        const bool done = flush == Z_FINISH ? status == Z_STREAM_END
                                            : png.zlib.avail_in == 0 && png.zlib.avail_out > 0;
        if (png.zlib.avail_out == 0 || (done && flush == Z_FINISH && filled > 0)) {
            if (!writeChunk(png.file, "IDAT", png.deflated.data(), filled)) {
                problem = systemError("cannot write the file");
                return false;
            }
            png.zlib.next_out = png.deflated.data();
            png.zlib.avail_out = static_cast<uInt>(kChunkBytes);
        }
        if (done) return true;
    }
}

void* openPng(const char* path, const char* format, int width, int height, int channels,
              int isFloat, int srgb, int compression, CrtImageErrorFn error, void* context) {
    if (std::strcmp(format, "png") != 0 || isFloat ||
        (channels != 1 && channels != 3 && channels != 4)) {
        error(context, "the built-in PNG writer stores 8-bit grey, RGB or RGBA images only");
        return nullptr;
    }
    try {
        auto png = std::make_unique<PngFile>();
        png->width = width;
        png->height = height;
        png->channels = channels;
        png->filtered.resize(1 + std::size_t(width) * std::size_t(channels));
        png->deflated.resize(kChunkBytes);
        // zlib's defaults except the strategy: Z_FILTERED suits filtered rows, as in libpng.
        if (deflateInit2(&png->zlib, compression, Z_DEFLATED, 15, 8, Z_FILTERED) != Z_OK) {
            error(context, "cannot start the compression");
            return nullptr;
        }
        png->zlibReady = true;
        png->zlib.next_out = png->deflated.data();
        png->zlib.avail_out = static_cast<uInt>(kChunkBytes);
        png->file = std::fopen(path, "wb");
        if (!png->file) {
            error(context, systemError("cannot create the file").c_str());
            return nullptr;
        }
        if (!writeHeader(*png, srgb != 0)) {
            error(context, systemError("cannot write the file").c_str());
            return nullptr;
        }
        return png.release();
    } catch (const std::bad_alloc&) {
        error(context, "out of memory");
        return nullptr;
    }
}

int writePngRows(void* image, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error,
                 void* context) {
    PngFile& png = *static_cast<PngFile*>(image);
    if (yBegin != png.nextRow || yEnd <= yBegin || yEnd > png.height) {
        error(context, "rows out of order");
        return 0;
    }
    const std::size_t rowBytes = png.filtered.size() - 1;
    const auto bytesPerPixel = static_cast<std::size_t>(png.channels);
    const auto* codes = static_cast<const unsigned char*>(pixels);
    std::string problem;
    for (int y = yBegin; y < yEnd; ++y, codes += rowBytes) {
        // Sub: each byte minus the same channel of the pixel to its left (modulo 256).
        unsigned char* out = png.filtered.data();
        out[0] = kFilterSub;
        std::memcpy(out + 1, codes, bytesPerPixel);
        for (std::size_t i = bytesPerPixel; i < rowBytes; ++i)
            out[1 + i] = static_cast<unsigned char>(codes[i] - codes[i - bytesPerPixel]);
        png.zlib.next_in = out;
        png.zlib.avail_in = static_cast<uInt>(png.filtered.size());
        if (!deflateInto(png, Z_NO_FLUSH, problem)) {
            error(context, problem.c_str());
            return 0;
        }
    }
    png.nextRow = yEnd;
    return 1;
}

int closePng(void* image, int abandon, CrtImageErrorFn error, void* context) {
    std::unique_ptr<PngFile> png(static_cast<PngFile*>(image));
    if (abandon) return 1;
    std::string problem;
    if (png->nextRow != png->height) {
        error(context, "the image is incomplete");
        return 0;
    }
    png->zlib.avail_in = 0;
    if (!deflateInto(*png, Z_FINISH, problem)) {
        error(context, problem.c_str());
        return 0;
    }
    if (!writeChunk(png->file, "IEND", nullptr, 0)) {
        error(context, systemError("cannot write the file").c_str());
        return 0;
    }
    std::FILE* file = png->file;
    png->file = nullptr;
    if (std::fclose(file) != 0) {
        error(context, systemError("cannot write the file").c_str());
        return 0;
    }
    return 1;
}

const CrtImageIoModule kPngWriter = {
    kCrtImageIoAbiVersion, nullptr, openPng, writePngRows, closePng, nullptr, nullptr,
};

} // namespace

const CrtImageIoModule& builtinPngWriter() {
    return kPngWriter;
}

} // namespace crt::tracer::image_io
