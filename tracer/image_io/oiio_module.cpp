// The OpenImageIO module (crt_image_io_oiio.so): the only source that includes OpenImageIO.
//
// It is dlopen'ed by crt_image_io so that OpenImageIO's 260 shared libraries load only in a
// process that reads or writes an image. OIIO's headers bundle their own fmt with fmt's
// include guards, so no <fmt/...> may appear in this file. Everything is built with hidden
// visibility except the entry point, and no exception leaves an extern "C" function.
#include "tracer/image_io/module_abi.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

struct ErrorSink {
    CrtImageErrorFn fn;
    void* context;
    int fail(const std::string& message) const {
        fn(context, message.c_str());
        return 0;
    }
};

// OIIO reports some failures on the object and some (a failed open or create) globally.
std::string oiioError(const std::string& objectError) {
    std::string message = objectError.empty() ? OIIO::geterror() : objectError;
    while (!message.empty() && message.back() == '\n') message.pop_back();
    return message.empty() ? "unknown OpenImageIO error" : message;
}

// Whether a PNG's chunks (a 4-byte big-endian length, a 4-byte type, the data and a 4-byte
// CRC each) all end within the file's `size` bytes.
bool pngChunksFit(std::FILE* file, long size) {
    for (long at = 8; at + 8 <= size;) {
        unsigned char header[8];
        if (std::fseek(file, at, SEEK_SET) != 0 || std::fread(header, 1, sizeof header, file) != sizeof header)
            return true; // OpenImageIO reports a read error itself
        const long length = long(header[0]) << 24 | long(header[1]) << 16 | long(header[2]) << 8 | header[3];
        if (length > size - at - 12) return false;
        at += 12 + length;
    }
    return true;
}

enum class NameRead { Read, End, TooLong };

// Reads bytes up to a NUL into `text`, as OpenEXR reads an attribute's name or type name: at
// most `maxLength` bytes and the NUL. End: the file ends first; TooLong: no NUL within them.
NameRead readName(std::FILE* file, std::size_t maxLength, std::string& text) {
    text.clear();
    for (int c; (c = std::fgetc(file)) != EOF;) {
        if (c == 0) return NameRead::Read;
        if (text.size() == maxLength) return NameRead::TooLong;
        text += char(c);
    }
    return NameRead::End;
}

// Why an OpenEXR file's headers cannot be trusted, or empty. Each attribute is a name and a
// type name, each ending with a NUL byte, a 4-byte little-endian size, then the value; an
// empty name ends a header, and an empty header ends a multi-part file's. OpenEXR reserves
// the size before reading the value, and it reads a name longer than its limit (31 bytes, or
// 255 with the long-names flag) only up to that limit, going on from there as if the rest
// were the type name and the size. Where the header is cut short, OpenEXR reports that itself.
std::string exrHeaderRefusal(std::FILE* file, long size, const unsigned char* head) {
    const bool longNames = (head[5] & 0x04) != 0, multipart = (head[5] & 0x10) != 0;
    const std::size_t maxLength = longNames ? 255 : 31;
    if (std::fseek(file, 8, SEEK_SET) != 0) return {};
    std::string name, type;
    while (true) {
        bool emptyHeader = true;
        while (true) {
            NameRead read = readName(file, maxLength, name);
            if (read == NameRead::Read && name.empty()) break;
            if (read == NameRead::Read) read = readName(file, maxLength, type);
            if (read == NameRead::TooLong) return "damaged OpenEXR file: an attribute's name is too long";
            emptyHeader = false;
            unsigned char field[4];
            if (read == NameRead::End || std::fread(field, 1, sizeof field, file) != sizeof field) return {};
            const long length = long(std::int32_t(std::uint32_t(field[0]) | std::uint32_t(field[1]) << 8 |
                                                  std::uint32_t(field[2]) << 16 | std::uint32_t(field[3]) << 24));
            const long at = std::ftell(file);
            if (length < 0 || at < 0 || length > size - at)
                return "damaged OpenEXR file: a header attribute is longer than the file";
            if (std::fseek(file, at + length, SEEK_SET) != 0) return {};
        }
        if (!multipart || emptyHeader) return {};
    }
}

// Files OpenImageIO 2.4 cannot be trusted with, told by their bytes before it opens them
// (found by tests/fuzz/fuzz_image); the reason to refuse `path`, or empty.
// - Maya IFF ("FOR4", "FOR8"): the reader aborts the process on a failed assertion while it
//   reads a damaged header, even when OpenImageIO only tries it on a file of unknown format.
// - PNG, DPX and OpenEXR: libpng reserves the length a chunk announces (up to 2 GiB), the DPX
//   reader the user data length the header announces, OpenEXR the size a header attribute
//   announces, before reading them; nothing limits any of them, so such a length beyond the
//   end of the file is refused first.
std::string refusedBeforeOpen(const char* path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
    if (!file) return {}; // OpenImageIO says why
    unsigned char head[36] = {};
    const std::size_t got = std::fread(head, 1, sizeof head, file.get());
    if (got < 8) return {};
    if (std::memcmp(head, "FOR4", 4) == 0 || std::memcmp(head, "FOR8", 4) == 0)
        return "IFF images are not supported";
    std::fseek(file.get(), 0, SEEK_END);
    const long size = std::ftell(file.get());
    if (std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0 && !pngChunksFit(file.get(), size))
        return "damaged PNG file: a chunk is longer than the file";
    // OpenEXR: the magic number, then a version byte and flags, 0x1000 for a multi-part file.
    if (std::memcmp(head, "\x76\x2f\x31\x01", 4) == 0) {
        if (std::string refusal = exrHeaderRefusal(file.get(), size, head); !refusal.empty()) return refusal;
    }
    const bool dpxBigEndian = std::memcmp(head, "SDPX", 4) == 0;
    if ((dpxBigEndian || std::memcmp(head, "XPDS", 4) == 0) && got == sizeof head) {
        const unsigned char* field = head + 32; // the user data length
        const unsigned long length =
            dpxBigEndian ? (unsigned long)field[0] << 24 | field[1] << 16 | field[2] << 8 | field[3]
                         : (unsigned long)field[3] << 24 | field[2] << 16 | field[1] << 8 | field[0];
        if (length != 0xffffffffUL && length > (unsigned long)size)
            return "damaged DPX file: its user data is longer than the file";
    }
    return {};
}

// Whether OpenImageIO 2.4's RLA reader would abort the process on `path`: it accepts the
// 740-byte big-endian header (revision 0 or 0xFFFE, bit depths 0 to 32, channel types 0 to 4,
// the scanline offset table after it within the file) and then fails an assertion ("Invalid
// colour channel type") on type 3, of the color channels or of matte or auxiliary channels
// there are some of. RLA has no magic number: this asks exactly what the reader's own checks
// before that assertion ask.
bool rlaReaderWouldAbort(const char* path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
    unsigned char header[740];
    if (!file || std::fread(header, 1, sizeof header, file.get()) != sizeof header) return false;
    auto field = [&](int at) { return int(std::int16_t(std::uint16_t(header[at] << 8 | header[at + 1]))); };
    const int revision = field(26);
    if (revision != -2 && revision != 0) return false;
    for (int bits : {field(658), field(662), field(666)})
        if (bits < 0 || bits > 32) return false;
    const int colorType = field(18), matteType = field(660), auxType = field(664);
    for (int type : {colorType, matteType, auxType})
        if (type < 0 || type > 4) return false;
    const long scanlines = std::abs(field(12) - field(14)) + 1;
    if (std::fseek(file.get(), 0, SEEK_END) != 0 || std::ftell(file.get()) < long(sizeof header) + 4 * scanlines)
        return false;
    return colorType == 3 || (field(22) != 0 && matteType == 3) || (field(24) != 0 && auxType == 3);
}

std::string lowerExtension(std::string_view path) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
    std::string extension(path.substr(dot + 1));
    for (char& c : extension) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return extension;
}

std::unique_ptr<ImageInput> openInput(const char* path, const ErrorSink& sink) {
    if (const std::string refused = refusedBeforeOpen(path); !refused.empty()) {
        sink.fail(refused);
        return nullptr;
    }
    // Color channels of a PNG with alpha must come back as stored, not premultiplied:
    // the alpha is dropped, so premultiplying would darken every transparent pixel.
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    // First the reader of the file's extension alone, as OpenImageIO would. Only where that
    // one fails (or there is none) does OpenImageIO try every reader on the file, the RLA
    // reader among them, so only there are files refused that would make it abort: a valid
    // file of another format, named for it, is never taken for a damaged RLA file.
    std::unique_ptr<ImageInput> in;
    const std::string extension = lowerExtension(path);
    if (!extension.empty() && extension != "rla") {
        in = ImageInput::create(extension, false, &config);
        ImageSpec spec;
        if (in && !in->open(path, spec, config)) in.reset();
        (void)OIIO::geterror(); // the fallback below reports its own error
    }
    if (!in) {
        if (rlaReaderWouldAbort(path)) {
            sink.fail("damaged RLA file: invalid channel type");
            return nullptr;
        }
        in = ImageInput::open(path, &config);
    }
    if (!in) {
        sink.fail(oiioError(""));
        return nullptr;
    }
    if (std::string_view(in->format_name()) == "ico") {
        sink.fail("ICO images are not supported");
        return nullptr;
    }
    return in;
}

// The type to ask read_image for, to get the pixels as `wanted`: "no conversion" when every
// channel is stored as `wanted` already. OpenImageIO 2.4 reads straight into the caller's
// buffer only then; asked for a type, even the stored one, it converts through a buffer of
// 64 MiB that it allocates for every image, however small (tests/fuzz/README.md).
TypeDesc readType(const ImageSpec& spec, TypeDesc wanted) {
    return spec.format == wanted && spec.channelformats.empty() ? OIIO::TypeUnknown : wanted;
}

// OIIO converts integers to float by multiplying with 1/max, which is off by an ulp for many
// codes; dividing here makes an 8-bit code k read as exactly k / 255.0f, as the spec says.
template <class Int> bool readScaled(ImageInput& in, std::vector<float>& out) {
    std::vector<Int> raw(out.size());
    if (!in.read_image(0, 0, 0, in.spec().nchannels, readType(in.spec(), OIIO::BaseTypeFromC<Int>::value), raw.data()))
        return false;
    constexpr float max = float(std::numeric_limits<Int>::max());
    for (std::size_t i = 0; i < raw.size(); ++i) out[i] = float(raw[i]) / max;
    return true;
}

// Other formats (half, float, 32-bit integers …) convert as OIIO does: floats stay as stored.
// Those read as stored and are converted here, by the conversion OpenImageIO would use, to
// keep clear of its 64 MiB buffer (readType).
bool readFloats(ImageInput& in, std::vector<float>& out) {
    const ImageSpec& spec = in.spec();
    const std::size_t valueBytes = spec.format.size();
    if (spec.format == OIIO::TypeFloat || !spec.channelformats.empty() || valueBytes == 0)
        return in.read_image(0, 0, 0, spec.nchannels, readType(spec, OIIO::TypeFloat), out.data());
    std::vector<unsigned char> raw(out.size() * valueBytes);
    if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeUnknown, raw.data())) return false;
    constexpr std::size_t kBatch = std::size_t{1} << 24; // convert_pixel_values counts in int
    for (std::size_t at = 0; at < out.size(); at += kBatch) {
        const int count = int(std::min(kBatch, out.size() - at));
        if (!OIIO::convert_pixel_values(spec.format, raw.data() + at * valueBytes, OIIO::TypeFloat, out.data() + at, count))
            return false;
    }
    return true;
}

int readImage(const char* path, int* isInteger, CrtImageAllocFn alloc, CrtImageErrorFn error,
              void* context) {
    const ErrorSink sink{error, context};
    try {
        auto in = openInput(path, sink);
        if (!in) return 0;
        const ImageSpec& spec = in->spec();
        if (spec.deep) return sink.fail("deep images are not supported");
        if (spec.depth > 1) return sink.fail("volume images are not supported");
        const int width = spec.width, height = spec.height, channels = spec.nchannels;
        if (width < 1 || height < 1 || channels < 1) return sink.fail("the image is empty");

        // Asked first, with the header's size: the host may refuse the image before its
        // pixels are read or decoded (a small file can claim a huge image).
        float* out = alloc(context, width, height);
        if (!out) return sink.fail("out of memory");
        std::vector<float> stored(std::size_t(width) * height * channels);
        const bool ok = spec.format == OIIO::TypeUInt8    ? readScaled<std::uint8_t>(*in, stored)
                        : spec.format == OIIO::TypeUInt16 ? readScaled<std::uint16_t>(*in, stored)
                                                          : readFloats(*in, stored);
        if (!ok) return sink.fail(oiioError(in->geterror()));

        // One or two channels are grey (and alpha): replicate the grey. Otherwise the first
        // three are RGB and any further (alpha, depth …) are dropped.
        const bool grey = channels < 3;
        const std::size_t pixels = std::size_t(width) * height;
        for (std::size_t i = 0; i < pixels; ++i) {
            const float* s = &stored[i * channels];
            float* d = &out[i * 3];
            d[0] = s[0];
            d[1] = grey ? s[0] : s[1];
            d[2] = grey ? s[0] : s[2];
        }
        if (isInteger) *isInteger = spec.format.is_floating_point() ? 0 : 1;
        return 1;
    } catch (const std::exception& e) {
        return sink.fail(e.what());
    } catch (...) {
        return sink.fail("unknown exception in the image module");
    }
}

// An image being written band by band.
struct OpenOutput {
    std::unique_ptr<ImageOutput> out;
    TypeDesc type;
    int channels;
};

void* openImage(const char* path, const char* format, int width, int height, int channels,
                int isFloat, int srgb, int /*pngCompression: PNG is written by png_writer*/,
                CrtImageErrorFn error, void* context) {
    const ErrorSink sink{error, context};
    try {
        // Created by format name, because the host writes to a temporary file whose name
        // does not end in the real extension.
        auto out = ImageOutput::create(format);
        if (!out) {
            sink.fail(oiioError(""));
            return nullptr;
        }
        const TypeDesc type = isFloat ? OIIO::TypeFloat : OIIO::TypeUInt8;
        ImageSpec spec(width, height, channels, type);
        if (srgb) spec.attribute("oiio:ColorSpace", "sRGB");
        // A fourth channel is straight alpha, stored as given: without this, PNG and TIFF
        // would take the color as premultiplied and divide it by alpha.
        spec.attribute("oiio:UnassociatedAlpha", 1);
        if (!out->open(path, spec)) {
            sink.fail(oiioError(out->geterror()));
            return nullptr;
        }
        return new OpenOutput{std::move(out), type, channels};
    } catch (const std::exception& e) {
        sink.fail(e.what());
    } catch (...) {
        sink.fail("unknown exception in the image module");
    }
    return nullptr;
}

int writeRows(void* image, int yBegin, int yEnd, const void* pixels, CrtImageErrorFn error,
              void* context) {
    const ErrorSink sink{error, context};
    try {
        OpenOutput& open = *static_cast<OpenOutput*>(image);
        if (open.out->write_scanlines(yBegin, yEnd, 0, open.type, pixels)) return 1;
        return sink.fail(oiioError(open.out->geterror()));
    } catch (const std::exception& e) {
        return sink.fail(e.what());
    } catch (...) {
        return sink.fail("unknown exception in the image module");
    }
}

int closeImage(void* image, int abandon, CrtImageErrorFn error, void* context) {
    const ErrorSink sink{error, context};
    std::unique_ptr<OpenOutput> open(static_cast<OpenOutput*>(image));
    try {
        if (open->out->close() || abandon) return 1;
        return sink.fail(oiioError(open->out->geterror()));
    } catch (const std::exception& e) {
        return sink.fail(e.what());
    } catch (...) {
        return sink.fail("unknown exception in the image module");
    }
}

int writeAnimatedGif(const char* path, int width, int height, int channels, int frameCount,
                     const std::uint8_t* const* frames, int fpsNumerator, int fpsDenominator,
                     CrtImageErrorFn error, void* context) {
    const ErrorSink sink{error, context};
    try {
        auto out = ImageOutput::create("gif");
        if (!out) return sink.fail(oiioError(""));
        ImageSpec spec(width, height, channels, OIIO::TypeUInt8);
        const int fps[2] = {fpsNumerator, fpsDenominator};
        spec.attribute("FramesPerSecond", OIIO::TypeRational, fps);
        spec.attribute("oiio:Movie", 1);
        spec.attribute("oiio:LoopCount", 0); // forever
        const std::vector<ImageSpec> specs(std::size_t(frameCount), spec);
        if (!out->open(path, frameCount, specs.data()))
            return sink.fail(oiioError(out->geterror()));
        for (int i = 0; i < frameCount; ++i) {
            if (i > 0 && !out->open(path, specs[i], ImageOutput::AppendSubimage))
                return sink.fail(oiioError(out->geterror()));
            if (!out->write_image(OIIO::TypeUInt8, frames[i]))
                return sink.fail(oiioError(out->geterror()));
        }
        if (!out->close()) return sink.fail(oiioError(out->geterror()));
        return 1;
    } catch (const std::exception& e) {
        return sink.fail(e.what());
    } catch (...) {
        return sink.fail("unknown exception in the image module");
    }
}

int describeImage(const char* path, CrtImageInfo* info, CrtImageErrorFn error, void* context) {
    const ErrorSink sink{error, context};
    try {
        auto in = openInput(path, sink);
        if (!in) return 0;
        const ImageSpec spec = in->spec(); // a copy: seek_subimage replaces in->spec()
        *info = CrtImageInfo{};
        info->width = spec.width;
        info->height = spec.height;
        info->channels = spec.nchannels;
        info->isInteger = spec.format.is_floating_point() ? 0 : 1;
        int subimages = 1;
        while (in->seek_subimage(subimages, 0)) ++subimages;
        info->subimages = subimages;
        if (const OIIO::ParamValue* p = spec.find_attribute("FramesPerSecond")) {
            if (p->type() == OIIO::TypeRational) {
                const int* r = static_cast<const int*>(p->data());
                info->fpsNumerator = r[0];
                info->fpsDenominator = r[1];
            } else if (p->type() == OIIO::TypeFloat) {
                // Kept to a thousandth: enough for a check, and still a rational.
                info->fpsNumerator = int(*static_cast<const float*>(p->data()) * 1000.0f + 0.5f);
                info->fpsDenominator = 1000;
            }
        }
        info->loopCount =
            spec.get_int_attribute("oiio:LoopCount", spec.get_int_attribute("gif:LoopCount", -1));
        std::strncpy(info->format, in->format_name(), sizeof info->format - 1);
        return 1;
    } catch (const std::exception& e) {
        return sink.fail(e.what());
    } catch (...) {
        return sink.fail("unknown exception in the image module");
    }
}

constexpr CrtImageIoModule kModule{
    kCrtImageIoAbiVersion, readImage,    openImage, writeRows, closeImage,
    writeAnimatedGif,      describeImage};

} // namespace

extern "C" __attribute__((visibility("default"))) const CrtImageIoModule* crt_image_io_module() {
    return &kModule;
}
