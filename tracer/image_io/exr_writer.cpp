// OpenEXR output through the OpenEXR library: a streamed writer behind the module table's
// writing entries.
#include "tracer/image_io/exr_writer.hpp"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>

namespace crt::tracer::image_io {
namespace {

/// The file under OpenEXR's writer, through stdio so that a failure keeps errno's reason. The
/// writer writes its table of line offsets when it is destroyed and swallows any error there,
/// so the stream keeps the first failure for closeImage to report.
class FileStream : public Imf::OStream {
public:
    FileStream(const char* path, std::FILE* file) : Imf::OStream(path), file_(file) {}

    void write(const char c[], int n) override {
        if (std::fwrite(c, 1, static_cast<size_t>(n), file_) != static_cast<size_t>(n)) fail("cannot write the file");
    }
    uint64_t tellp() override {
        const off_t at = ftello(file_);
        if (at < 0) fail("cannot write the file");
        return static_cast<uint64_t>(at);
    }
    void seekp(uint64_t position) override {
        if (fseeko(file_, static_cast<off_t>(position), SEEK_SET) != 0) fail("cannot write the file");
    }
    const std::string& failure() const { return failure_; }

private:
    [[noreturn]] void fail(const char* what) {
        if (failure_.empty()) failure_ = std::string(what) + ": " + std::strerror(errno);
        throw Iex::IoExc(failure_);
    }
    std::FILE* file_;
    std::string failure_;
};

struct ExrFile {
    std::FILE* file = nullptr;
    std::unique_ptr<FileStream> stream;
    std::unique_ptr<Imf::OutputFile> out;
    int width = 0, height = 0, channels = 0;
    int nextRow = 0;
    std::string message; ///< why the write failed, kept by the first error

    ~ExrFile() {
        out.reset();
        if (file) std::fclose(file);
    }
};

const char* channelName(int channels, int c) {
    static const char* const kRgba[] = {"R", "G", "B", "A"};
    return channels == 1 ? "Y" : kRgba[c];
}

void* openExr(const char* path, const char* format, int width, int height, int channels, int isFloat, int /*srgb*/,
              int /*pngCompression*/, CrtImageErrorFn error, void* context) {
    if (std::strcmp(format, "openexr") != 0 || !isFloat || (channels != 1 && channels != 3 && channels != 4)) {
        error(context, "the built-in OpenEXR writer stores float Y, RGB or RGBA images only");
        return nullptr;
    }
    try {
        auto exr = std::make_unique<ExrFile>();
        exr->width = width;
        exr->height = height;
        exr->channels = channels;
        exr->file = std::fopen(path, "wb");
        if (!exr->file) {
            error(context, (std::string("cannot create the file: ") + std::strerror(errno)).c_str());
            return nullptr;
        }
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (int c = 0; c < channels; ++c) header.channels().insert(channelName(channels, c), Imf::Channel(Imf::FLOAT));
        exr->stream = std::make_unique<FileStream>(path, exr->file);
        exr->out = std::make_unique<Imf::OutputFile>(*exr->stream, header);
        return exr.release();
    } catch (const std::exception& e) {
        error(context, e.what());
    } catch (...) {
        error(context, "unknown error in the OpenEXR writer");
    }
    return nullptr;
}

int writeExrRows(void* image, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error, void* context) {
    ExrFile& exr = *static_cast<ExrFile*>(image);
    if (!exr.message.empty()) {
        error(context, exr.message.c_str()); // the writer's state after an error must not be used again
        return 0;
    }
    if (yBegin != exr.nextRow || yEnd <= yBegin || yEnd > exr.height) {
        error(context, "rows out of order");
        return 0;
    }
    try {
        const size_t pixelBytes = sizeof(float) * static_cast<size_t>(exr.channels);
        const Imath::V2i origin(0, yBegin);
        Imf::FrameBuffer rows;
        for (int c = 0; c < exr.channels; ++c)
            rows.insert(channelName(exr.channels, c),
                        Imf::Slice::Make(Imf::FLOAT, static_cast<const float*>(pixels) + c, origin, exr.width,
                                         yEnd - yBegin, pixelBytes, pixelBytes * static_cast<size_t>(exr.width)));
        exr.out->setFrameBuffer(rows);
        exr.out->writePixels(yEnd - yBegin);
        exr.nextRow = yEnd;
        return 1;
    } catch (const std::exception& e) {
        exr.message = e.what();
    } catch (...) {
        exr.message = "unknown error in the OpenEXR writer";
    }
    error(context, exr.message.c_str());
    return 0;
}

int closeExr(void* image, int abandon, CrtImageErrorFn error, void* context) {
    std::unique_ptr<ExrFile> exr(static_cast<ExrFile*>(image));
    if (abandon) return 1;
    if (exr->message.empty() && exr->nextRow != exr->height) exr->message = "the image is incomplete";
    if (exr->message.empty()) {
        exr->out.reset(); // writes the table of line offsets
        if (!exr->stream->failure().empty()) exr->message = exr->stream->failure();
        // Closed here, not in the destructor, because a full disk may show only now.
        std::FILE* file = exr->file;
        exr->file = nullptr;
        if (std::fclose(file) != 0 && exr->message.empty())
            exr->message = std::string("cannot write the file: ") + std::strerror(errno);
    }
    if (exr->message.empty()) return 1;
    error(context, exr->message.c_str());
    return 0;
}

const CrtImageIoModule kExrWriter = {
    kCrtImageIoAbiVersion, nullptr, openExr, writeExrRows, closeExr, nullptr, nullptr,
};

} // namespace

const CrtImageIoModule& builtinExrWriter() {
    return kExrWriter;
}

} // namespace crt::tracer::image_io
