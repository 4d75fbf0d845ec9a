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

// The host's limit on the size of an image, asked before anything is reserved for one.
struct SizeCheck {
    CrtImageSizeFn accepts;
    void* context;
    bool operator()(long long width, long long height) const { return accepts(context, width, height) != 0; }
};

// What the module fails with when the host refused a size: the host reports its own reason.
constexpr const char* kSizeRefused = "the image is larger than allowed";

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

// Reads a little-endian 32-bit integer, signed or not; false at the end of the file.
bool readInt32(std::FILE* file, long long& value, bool isSigned = true) {
    unsigned char bytes[4];
    if (std::fread(bytes, 1, sizeof bytes, file) != sizeof bytes) return false;
    const std::uint32_t bits = std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                               std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24;
    value = isSigned ? (long long)std::int32_t(bits) : (long long)bits;
    return true;
}

// The number of bytes OpenEXR reads for a value of `type` whatever size the file declares for
// it, or 0 for a type whose values it reads by their declared size (string, opaque …) or by
// their own layout (chlist, preview: checked apart).
long exrFixedSize(const std::string& type) {
    static const std::pair<const char*, long> sizes[] = {
        {"box2i", 16},   {"box2f", 16},          {"chromaticities", 32}, {"compression", 1},
        {"double", 8},   {"envmap", 1},          {"float", 4},           {"int", 4},
        {"keycode", 28}, {"lineOrder", 1},       {"m33f", 36},           {"m33d", 72},
        {"m44f", 64},    {"m44d", 128},          {"rational", 8},        {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8},             {"v2f", 8},             {"v2d", 16},
        {"v3i", 12},     {"v3f", 12},            {"v3d", 24},            {"deepImageState", 1}};
    for (const auto& [name, size] : sizes)
        if (type == name) return size;
    return 0;
}

// The sizes one OpenEXR header gives, as far as the checks need them.
struct ExrSizes {
    long long width = 0, height = 0;         // of the data window
    long long tileWidth = 0, tileHeight = 0; // of a tiled part's tiles
    int compression = 0;
};

// How many bytes of a channel list OpenEXR reads: entries of a name, its NUL and 16 bytes,
// up to an empty name. -1 when a name is longer than OpenEXR reads or the file ends first.
long exrChannelListLength(std::FILE* file, std::size_t maxLength) {
    long length = 0;
    std::string name;
    while (true) {
        if (readName(file, maxLength, name) != NameRead::Read) return -1;
        length += long(name.size()) + 1;
        if (name.empty()) return length;
        if (std::fseek(file, 16, SEEK_CUR) != 0) return -1;
        length += 16;
    }
}

// Why the value of one attribute (at the file's position, `length` bytes declared) cannot be
// trusted, or empty; learns the header's sizes on the way. OpenEXR reads a value of a known
// type by the type's own layout: were that not the declared size, it would go on reading the
// next attribute from somewhere else than the check does.
std::string exrValueRefusal(std::FILE* file, const std::string& name, const std::string& type, long length,
                            std::size_t maxLength, ExrSizes& sizes) {
    const std::string damaged = "damaged OpenEXR file: attribute '" + name + "' of type " + type;
    if (const long fixed = exrFixedSize(type); fixed != 0 && fixed != length)
        return damaged + " declares " + std::to_string(length) + " bytes, not " + std::to_string(fixed);
    long long a = 0, b = 0, c = 0, d = 0;
    if (type == "chlist") {
        if (exrChannelListLength(file, maxLength) != length) return damaged + " does not end where it says";
    } else if (type == "preview") {
        // Its width and height, then 4 bytes a pixel: OpenEXR reserves them before it reads.
        if (!readInt32(file, a, false) || !readInt32(file, b, false)) return {};
        const unsigned long long pixels = (unsigned long long)a * (unsigned long long)b; // < 2^64
        if (length < 8 || (length - 8) % 4 != 0 || pixels != (unsigned long long)(length - 8) / 4)
            return damaged + " does not end where it says";
    } else if (type == "box2i" && name == "dataWindow") {
        if (!readInt32(file, a) || !readInt32(file, b) || !readInt32(file, c) || !readInt32(file, d)) return {};
        sizes.width = c - a + 1;
        sizes.height = d - b + 1;
    } else if (type == "tiledesc" && name == "tiles") {
        if (!readInt32(file, a, false) || !readInt32(file, b, false)) return {};
        sizes.tileWidth = a;
        sizes.tileHeight = b;
    } else if (type == "compression" && name == "compression") {
        sizes.compression = std::fgetc(file);
    }
    return {};
}

// The lines of pixels OpenEXR decompresses at once with `compression` (NONE, RLE, ZIPS: 1;
// ZIP, PXR24: 16; PIZ, B44, B44A, DWAA: 32; DWAB: 256), whatever the image's height.
long long exrLinesAtOnce(int compression) {
    static constexpr long long lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression >= 0 && compression < 10 ? lines[compression] : 1;
}

// Why an OpenEXR file's headers cannot be trusted, or empty. Each attribute is a name and a
// type name, each ending with a NUL byte, a 4-byte little-endian size, then the value; an
// empty name ends a header, and an empty header ends a multi-part file's. OpenEXR reserves
// the size before reading the value, and it reads a name longer than its limit (31 bytes, or
// 255 with the long-names flag) only up to that limit, going on from there as if the rest
// were the type name and the size. When it opens a file it reserves a line buffer as wide as
// the data window (and tiles as large as they say): those sizes go to the host's limit.
// Where the header is cut short, OpenEXR reports that itself.
std::string exrHeaderRefusal(std::FILE* file, long size, const unsigned char* head, const SizeCheck& accepts) {
    const bool longNames = (head[5] & 0x04) != 0, multipart = (head[5] & 0x10) != 0;
    const std::size_t maxLength = longNames ? 255 : 31;
    if (std::fseek(file, 8, SEEK_SET) != 0) return {};
    std::string name, type;
    while (true) {
        bool emptyHeader = true;
        ExrSizes sizes;
        while (true) {
            NameRead read = readName(file, maxLength, name);
            if (read == NameRead::Read && name.empty()) break;
            if (read == NameRead::Read) read = readName(file, maxLength, type);
            if (read == NameRead::TooLong) return "damaged OpenEXR file: an attribute's name is too long";
            emptyHeader = false;
            long long length = 0;
            if (read == NameRead::End || !readInt32(file, length)) return {};
            const long at = std::ftell(file);
            if (length < 0 || at < 0 || length > size - at)
                return "damaged OpenEXR file: a header attribute is longer than the file";
            if (std::string refusal = exrValueRefusal(file, name, type, long(length), maxLength, sizes);
                !refusal.empty())
                return refusal;
            if (std::fseek(file, at + long(length), SEEK_SET) != 0) return {};
        }
        if (!accepts(sizes.width, std::max(sizes.height, exrLinesAtOnce(sizes.compression))) ||
            !accepts(sizes.tileWidth, sizes.tileHeight))
            return kSizeRefused;
        if (!multipart || emptyHeader) return {};
    }
}

// OpenImageIO 2.4's readers of these formats cannot be trusted with a damaged file (found by
// tests/fuzz/fuzz_image): IFF's aborts the process on a failed assertion in the header, ICO's
// writes past its buffer, FITS' reserves gigabytes while it reads a header, RLA's aborts on a
// channel type and decodes some run-length data forever. None of them is asked to open a
// file, not even to guess its format.
constexpr std::string_view kRefusedFormats[] = {"fits", "ico", "iff", "rla"};

bool refusedFormat(std::string_view format) {
    return std::find(std::begin(kRefusedFormats), std::end(kRefusedFormats), format) != std::end(kRefusedFormats);
}

// Files OpenImageIO 2.4 cannot be trusted with, told by their bytes before it opens them
// (found by tests/fuzz/fuzz_image); the reason to refuse `path`, or empty.
// - PNG, DPX and OpenEXR: libpng reserves the length a chunk announces (up to 2 GiB), the DPX
//   reader the user data length the header announces, OpenEXR the size a header attribute
//   announces, before reading them; nothing limits any of them, so such a length beyond the
//   end of the file is refused first.
// - GIF and OpenEXR: their readers reserve memory for the size the header claims while they
//   open the file (GIF's the logical screen, OpenEXR's its line buffers), so the host's limit
//   on that size is asked first.
std::string refusedBeforeOpen(const char* path, const SizeCheck& accepts) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
    if (!file) return {}; // OpenImageIO says why
    unsigned char head[36] = {};
    const std::size_t got = std::fread(head, 1, sizeof head, file.get());
    if (got < 10) return {};
    std::fseek(file.get(), 0, SEEK_END);
    const long size = std::ftell(file.get());
    if (std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0 && !pngChunksFit(file.get(), size))
        return "damaged PNG file: a chunk is longer than the file";
    // giflib takes a file for a GIF by its first 3 bytes, whatever version the next 3 say.
    if (std::memcmp(head, "GIF", 3) == 0 && !accepts(head[6] | head[7] << 8, head[8] | head[9] << 8))
        return kSizeRefused;
    // OpenEXR: the magic number, then a version byte and flags, 0x1000 for a multi-part file.
    if (std::memcmp(head, "\x76\x2f\x31\x01", 4) == 0) {
        if (std::string refusal = exrHeaderRefusal(file.get(), size, head, accepts); !refusal.empty())
            return refusal;
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

std::string lowerExtension(std::string_view path) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
    std::string extension(path.substr(dot + 1));
    for (char& c : extension) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return extension;
}

// "fits" → "FITS"
std::string upperCase(std::string_view text) {
    std::string upper(text);
    for (char& c : upper) c = char(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    return upper;
}

std::unique_ptr<ImageInput> openInput(const char* path, const SizeCheck& accepts, const ErrorSink& sink) {
    if (const std::string refused = refusedBeforeOpen(path, accepts); !refused.empty()) {
        sink.fail(refused);
        return nullptr;
    }
    // Color channels of a PNG with alpha must come back as stored, not premultiplied:
    // the alpha is dropped, so premultiplying would darken every transparent pixel.
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    // First the reader of the file's extension, as OpenImageIO would; where that one fails or
    // there is none, every other reader OpenImageIO has, in its order, but those refused.
    std::string tried, firstError;
    if (const std::string extension = lowerExtension(path); !extension.empty()) {
        if (auto in = ImageInput::create(extension, false, &config)) {
            tried = in->format_name();
            if (refusedFormat(tried)) {
                sink.fail(upperCase(tried) + " images are not supported");
                return nullptr;
            }
            ImageSpec spec;
            if (in->open(path, spec, config)) return in;
            firstError = oiioError(in->geterror());
        }
        (void)OIIO::geterror();
    }
    const std::string formats = OIIO::get_string_attribute("input_format_list");
    for (std::size_t at = 0; at < formats.size();) {
        const std::size_t comma = std::min(formats.find(',', at), formats.size());
        const std::string format = formats.substr(at, comma - at);
        at = comma + 1;
        if (format == tried || refusedFormat(format)) continue;
        auto in = ImageInput::create(format, false, &config);
        ImageSpec spec;
        if (in && in->open(path, spec, config)) return in;
        if (in) (void)in->geterror();
        (void)OIIO::geterror();
    }
    sink.fail(firstError.empty() ? "not an image file OpenImageIO reads" : firstError);
    return nullptr;
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

int readImage(const char* path, int* isInteger, CrtImageSizeFn acceptsSize, CrtImageAllocFn alloc,
              CrtImageErrorFn error, void* context) {
    const ErrorSink sink{error, context};
    const SizeCheck accepts{acceptsSize, context};
    try {
        auto in = openInput(path, accepts, sink);
        if (!in) return 0;
        const ImageSpec& spec = in->spec();
        if (spec.deep) return sink.fail("deep images are not supported");
        if (spec.depth > 1) return sink.fail("volume images are not supported");
        const int width = spec.width, height = spec.height, channels = spec.nchannels;
        if (width < 1 || height < 1 || channels < 1) return sink.fail("the image is empty");

        // The host may refuse the image before its pixels are read or decoded (a small file
        // can claim a huge image).
        if (!accepts(width, height)) return sink.fail(kSizeRefused);
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

int describeImage(const char* path, CrtImageInfo* info, CrtImageSizeFn acceptsSize, CrtImageErrorFn error,
                  void* context) {
    const ErrorSink sink{error, context};
    const SizeCheck accepts{acceptsSize, context};
    try {
        auto in = openInput(path, accepts, sink);
        if (!in) return 0;
        const ImageSpec spec = in->spec(); // a copy: seek_subimage replaces in->spec()
        if (!accepts(spec.width, spec.height)) return sink.fail(kSizeRefused);
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
