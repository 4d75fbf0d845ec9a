// The OpenImageIO module (crt_image_io_oiio.so): the only source that includes OpenImageIO.
//
// It is dlopen'ed by crt_image_io so that OpenImageIO's 260 shared libraries load only in a
// process that reads or writes an image. OIIO's headers bundle their own fmt with fmt's
// include guards, so no <fmt/...> may appear in this file. Everything is built with hidden
// visibility except the entry point, and no exception leaves an extern "C" function.
#include "tracer/image_io/header_checks.hpp"
#include "tracer/image_io/module_abi.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

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
namespace Strutil = OIIO::Strutil;
using crt::tracer::image_io::kSizeRefused;
using crt::tracer::image_io::refusedBeforeOpen;
using crt::tracer::image_io::SizeCheck;

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

// OpenImageIO 2.4's readers of these formats cannot be trusted with a damaged file (found by
// tests/fuzz/fuzz_image): IFF's aborts the process on a failed assertion in the header, ICO's
// writes past its buffer, FITS' reserves gigabytes while it reads a header, RLA's aborts on a
// channel type and decodes some run-length data forever, SGI's reads through a null pointer
// or takes 4 GB and 6 s for a 109-byte file, HEIF's copies rows of the size the header
// announces out of a smaller decoded image. None of them is asked to open a file, not even
// to guess its format.
constexpr std::string_view kRefusedFormats[] = {"fits", "heif", "ico", "iff", "rla", "sgi"};

bool refusedFormat(std::string_view format) {
    return std::find(std::begin(kRefusedFormats), std::end(kRefusedFormats), format) != std::end(kRefusedFormats);
}

std::unique_ptr<ImageInput> openInput(const char* path, const SizeCheck& accepts, const ErrorSink& sink) {
    if (const std::string refused = refusedBeforeOpen(path, accepts); !refused.empty()) {
        sink.fail(refused);
        return nullptr;
    }
    // Color channels of a PNG with alpha must come back as stored, not premultiplied: a
    // texture's colour and its coverage are used apart, so premultiplying would darken
    // every transparent pixel.
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    // First the reader of the file's extension, as OpenImageIO would; where that one fails or
    // there is none, every other reader OpenImageIO has, in its order, but those refused.
    std::string tried, firstError;
    if (const std::string extension = Strutil::lower(OIIO::Filesystem::extension(path, false));
        !extension.empty()) {
        if (auto in = ImageInput::create(extension, false, &config)) {
            tried = in->format_name();
            if (refusedFormat(tried)) {
                sink.fail(Strutil::upper(tried) +
                          " images are not supported (convert the file to PNG, TIFF or OpenEXR)");
                return nullptr;
            }
            ImageSpec spec;
            if (in->open(path, spec, config)) return in;
            firstError = oiioError(in->geterror());
        }
        (void)OIIO::geterror();
    }
    const std::string formats = OIIO::get_string_attribute("input_format_list");
    for (const std::string_view formatName : Strutil::splitsv(formats, ",")) {
        const std::string format(formatName);
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

// Whether OpenImageIO 2.4 must be asked for a TIFF a row at a time; asked for many rows:
// - of a min-is-white image of more than one channel stored in deflated strips of 8- or 16-bit
//   values, it inverts a strip's length times the channel count from each strip's start, past
//   the end of the caller's buffer (found by tests/fuzz/fuzz_image; a valid grey-and-alpha
//   file is enough); a row at a time, it inverts the row it decoded;
// - it rounds their count up to a multiple of the rows per strip, in `int`: a strip that
//   claims nearly 2^31 rows or more made a 16 × 16 file take forever or abort. A strip longer
//   than the image holds the image, however long it claims to be; OpenImageIO leaves the
//   count out of the spec where it does not fit in `int`, and where the file does not give
//   it (one strip).
constexpr int kTiffMinIsWhite = 0; // TIFF 6.0's PhotometricInterpretation for it

bool isMinIsWhite(const ImageSpec& spec) {
    return spec.get_int_attribute("tiff:PhotometricInterpretation", -1) == kTiffMinIsWhite;
}

bool mustReadByRows(const ImageInput& in) {
    const ImageSpec& spec = in.spec();
    if (std::string_view(in.format_name()) != "tiff" || spec.tile_width != 0) return false;
    const int rowsPerStrip = spec.get_int_attribute("tiff:RowsPerStrip", 0);
    return rowsPerStrip < 1 || rowsPerStrip > spec.height ||
           (spec.nchannels > 1 && isMinIsWhite(spec));
}

// Every pixel of the image, as `type` (readType), into `data`.
bool readPixels(ImageInput& in, TypeDesc type, void* data) {
    const ImageSpec& spec = in.spec();
    if (!mustReadByRows(in)) return in.read_image(0, 0, 0, spec.nchannels, type, data);
    const std::size_t valueBytes = type == OIIO::TypeUnknown ? spec.format.size() : type.size();
    const std::size_t rowBytes = std::size_t(spec.width) * spec.nchannels * valueBytes;
    auto* row = static_cast<unsigned char*>(data);
    for (int y = spec.y; y < spec.y + spec.height; ++y, row += rowBytes)
        if (!in.read_scanline(y, spec.z, type, row)) return false;
    return true;
}

// OIIO converts integers to float by multiplying with 1/max, which is off by an ulp for many
// codes; dividing here makes an 8-bit code k read as exactly k / 255.0f, as the spec says.
template <class Int> bool readScaled(ImageInput& in, std::vector<float>& out) {
    std::vector<Int> raw(out.size());
    if (!readPixels(in, readType(in.spec(), OIIO::BaseTypeFromC<Int>::value), raw.data()))
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
        return readPixels(in, readType(spec, OIIO::TypeFloat), out.data());
    std::vector<unsigned char> raw(out.size() * valueBytes);
    if (!readPixels(in, OIIO::TypeUnknown, raw.data())) return false;
    constexpr std::size_t kBatch = std::size_t{1} << 24; // convert_pixel_values counts in int
    for (std::size_t at = 0; at < out.size(); at += kBatch) {
        const int count = int(std::min(kBatch, out.size() - at));
        if (!OIIO::convert_pixel_values(spec.format, raw.data() + at * valueBytes, OIIO::TypeFloat, out.data() + at, count))
            return false;
    }
    return true;
}

// OpenImageIO reads an image in chunks of rows counted in `int` from the data window's first
// row, which a header may put anywhere: a DPX whose row origin is within 2^24 of the largest
// `int` overflowed that count, and a tiny file turned into millions of single-row reads
// (tests/fuzz/README.md). Windows ending within 2^30 of the origin leave the chunks (at most
// 2^26 rows) room; real images lie far nearer.
bool dataWindowInRange(const ImageSpec& spec) {
    constexpr std::int64_t kLimit = std::int64_t{1} << 30;
    auto inRange = [](std::int64_t origin, std::int64_t size) {
        return origin >= -kLimit && origin + size <= kLimit;
    };
    return inRange(spec.x, spec.width) && inRange(spec.y, spec.height) && inRange(spec.z, spec.depth);
}

// OpenImageIO 2.4's TIFF reader unpacks CMYK values of other than 8 or 16 bits into a buffer
// sized for the RGB it converts them to, writing past its end (fixed upstream after 2.4, in
// OpenImageIO's pull request 5296; a valid 64 × 64 file of 4-bit CMYK is enough). The bits
// of such a file's values, or zero.
int cmykBitsUnpackedPastBuffer(const ImageInput& in) {
    constexpr int kTiffSeparated = 5; // TIFF 6.0's PhotometricInterpretation for CMYK
    const ImageSpec& spec = in.spec();
    if (std::string_view(in.format_name()) != "tiff" ||
        spec.get_int_attribute("tiff:PhotometricInterpretation", -1) != kTiffSeparated)
        return 0;
    const int bits = spec.get_int_attribute("oiio:BitsPerSample", 8);
    return bits == 8 || bits == 16 ? 0 : bits;
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
        if (!dataWindowInRange(spec))
            return sink.fail("damaged image file: its pixels lie too far from the origin");
        if (const int bits = cmykBitsUnpackedPastBuffer(*in))
            return sink.fail("CMYK TIFF images of " + std::to_string(bits) +
                             "-bit values are not supported (convert the file to 8 or 16 bits)");

        // The host may refuse the image before its pixels are read or decoded (a small file
        // can claim a huge image).
        if (!accepts(width, height, channels)) return sink.fail(kSizeRefused);
        const int alpha = spec.alpha_channel < channels ? spec.alpha_channel : -1; // -1: none
        const int kept = alpha >= 0 ? 4 : 3;
        float* out = alloc(context, width, height, kept);
        if (!out) return sink.fail("out of memory");
        std::vector<float> stored(std::size_t(width) * height * channels);
        const bool ok = spec.format == OIIO::TypeUInt8    ? readScaled<std::uint8_t>(*in, stored)
                        : spec.format == OIIO::TypeUInt16 ? readScaled<std::uint16_t>(*in, stored)
                                                          : readFloats(*in, stored);
        if (!ok) return sink.fail(oiioError(in->geterror()));

        // One or two channels are grey (and alpha): replicate the grey. Otherwise the first
        // three are RGB; of any further, only alpha is kept.
        const bool grey = channels < 3;
        // OpenImageIO inverts every channel of a min-is-white TIFF; TIFF's photometric
        // interpretation is the colour's, so the alpha is inverted back.
        const bool alphaInverted = alpha >= 0 && isMinIsWhite(spec);
        const std::size_t pixels = std::size_t(width) * height;
        for (std::size_t i = 0; i < pixels; ++i) {
            const float* s = &stored[i * channels];
            float* d = &out[i * kept];
            d[0] = s[0];
            d[1] = grey ? s[0] : s[1];
            d[2] = grey ? s[0] : s[2];
            if (alpha >= 0) d[3] = alphaInverted ? 1 - s[alpha] : s[alpha];
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
        if (!accepts(spec.width, spec.height, spec.nchannels)) return sink.fail(kSizeRefused);
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
