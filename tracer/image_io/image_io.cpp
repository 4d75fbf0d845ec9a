// Image input and output: checks, quantisation and temporary files here, pixels through the
// module (or, for PNG, the built-in writer).
#include "tracer/image_io/image_io.hpp"

#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/gif_frame_delays.hpp"
#include "tracer/image_io/module_loader.hpp"
#include "tracer/image_io/exr_writer.hpp"
#include "tracer/image_io/png_writer.hpp"
#include "tracer/image_io/temporary_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>
#include <system_error>

namespace crt::tracer::image_io {
namespace {

namespace fs = std::filesystem;

/// How a format stores a fourth channel.
enum class AlphaStorage : std::uint8_t {
    None,          ///< not at all
    Straight,      ///< as given: PNG's and TIFF's unassociated alpha
    Premultiplied, ///< the color multiplied by it: OpenEXR's convention
};

struct OutputFormat {
    const char* extension;
    const char* oiioName;
    bool eightBit;
    bool needsRgb; ///< the format stores no single-channel images
    /// Its writer built in (png_writer, exr_writer), without the module; null: the module's.
    const CrtImageIoModule& (*builtinWriter)();
    AlphaStorage alpha;
};

constexpr OutputFormat kOutputFormats[] = {
    {".png", "png", true, false, builtinPngWriter, AlphaStorage::Straight},
    {".jpg", "jpeg", true, false, nullptr, AlphaStorage::None},
    {".jpeg", "jpeg", true, false, nullptr, AlphaStorage::None},
    {".tif", "tiff", true, false, nullptr, AlphaStorage::Straight},
    {".tiff", "tiff", true, false, nullptr, AlphaStorage::Straight},
    {".exr", "openexr", false, false, builtinExrWriter, AlphaStorage::Premultiplied},
    {".hdr", "hdr", false, true, nullptr, AlphaStorage::None},
    {".gif", "gif", true, true, nullptr, AlphaStorage::None},
};

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

const OutputFormat* outputFormatOf(const std::string& path) {
    const std::string ext = lowerExtension(path);
    for (const OutputFormat& format : kOutputFormats)
        if (ext == format.extension) return &format;
    return nullptr;
}

std::string supportedExtensions() {
    std::string list;
    for (const OutputFormat& format : kOutputFormats)
        list += (list.empty() ? "" : ", ") + std::string(format.extension);
    return list;
}

std::string quotedName(const std::string& path) {
    return "\"" + path + "\"";
}

// One context for the callbacks of a module call: the error text and, when reading, the image.
struct CallContext {
    std::string error;
    ImageBuffer* image = nullptr;
    uint64_t maxPixels = std::numeric_limits<uint64_t>::max(); ///< the largest image taken
    std::string refusal; ///< why acceptsSize refused the image, when it did
};

void storeError(void* context, const char* message) {
    static_cast<CallContext*>(context)->error = message ? message : "unknown error";
}

// Pixels of more than four channels count as the pixels of four holding as many values: the
// channels multiply what the image takes to read, and a small header may claim thousands.
int acceptsSize(void* context, long long width, long long height, int channels) {
    CallContext& call = *static_cast<CallContext*>(context);
    if (width <= 0 || height <= 0) return 1;
    // Counted in floating point: a header may claim 2^32 x 2^32.
    const double pixels = double(width) * double(height);
    const double asPixelsOfFour = pixels * std::max(channels, 4) / 4;
    if (asPixelsOfFour <= double(call.maxPixels)) return 1;
    const std::string size =
        "it is " + std::to_string(width) + " x " + std::to_string(height) + " pixels";
    const std::string allowed = std::to_string(call.maxPixels);
    call.refusal = pixels > double(call.maxPixels)
                       ? size + ", more than the " + allowed + " allowed"
                       : size + " of " + std::to_string(channels) +
                             " channels, more values than the " + allowed +
                             " pixels allowed hold at four channels each";
    call.refusal += "; raise the limit with --max-image-pixels";
    return 0;
}

float* allocatePixels(void* context, int width, int height, int channels) {
    ImageBuffer& image = *static_cast<CallContext*>(context)->image;
    if (channels != 3 && channels != 4) return nullptr;
    try {
        image.width = width;
        image.height = height;
        image.channels = channels;
        image.pixels.assign(std::size_t(width) * std::size_t(height) * channels, 0.0f);
        return image.pixels.data();
    } catch (const std::bad_alloc&) {
        return nullptr; // reported by the module as out of memory; no exception crosses C
    }
}

/// What a failed module call says: the host's refusal of the size, else the module's error.
const std::string& callFailure(const CallContext& call) {
    return call.refusal.empty() ? call.error : call.refusal;
}

bool checkSize(int width, int height, int channels, std::string& problem) {
    if (width < 1 || height < 1) {
        problem =
            "the image is empty (" + std::to_string(width) + " x " + std::to_string(height) + ")";
        return false;
    }
    if (channels != 1 && channels != 3 && channels != 4) {
        problem = "an image needs 1, 3 or 4 channels, not " + std::to_string(channels);
        return false;
    }
    return true;
}

bool checkBuffer(const ImageBuffer& image, std::string& problem) {
    if (!checkSize(image.width, image.height, image.channels, problem)) return false;
    const std::size_t expected =
        std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels);
    if (image.pixels.size() != expected) {
        problem = "the image holds " + std::to_string(image.pixels.size()) + " values instead of " +
                  std::to_string(expected);
        return false;
    }
    return true;
}

bool checkOptions(const WriteOptions& options, std::string& problem) {
    if (!(options.gamma > 0.0) || !std::isfinite(options.gamma)) {
        problem = "gamma must be a positive number";
        return false;
    }
    if (options.pngCompression < 0 || options.pngCompression > 9) {
        problem = "the PNG compression level must be 0 to 9";
        return false;
    }
    return true;
}

// GIF and HDR store only color: a grey image becomes three equal channels.
std::vector<float> expandGrey(std::span<const float> grey) {
    std::vector<float> rgb(grey.size() * 3);
    for (std::size_t i = 0; i < grey.size(); ++i)
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = grey[i];
    return rgb;
}

// The transfer function applies to color; a fourth channel is alpha, a coverage stored as is.
std::vector<std::uint8_t> quantiseColor(std::span<const float> values, int channels,
                                         const WriteOptions& options) {
    std::vector<std::uint8_t> codes = quantise8(values, options.gamma, options.srgb);
    if (channels == 4)
        for (std::size_t i = 3; i < values.size(); i += 4) codes[i] = encodeGamma8(values[i], 1.0);
    return codes;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    if (from.empty()) return text;
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

// Whether `path` can be written: its directory exists and it is not one.
bool checkTarget(const std::string& path, std::string& error) {
    const fs::path target(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        error = "cannot write " + quotedName(path) + ": the directory " + quotedName(dir.string()) +
                " does not exist";
        return false;
    }
    if (fs::is_directory(target, ec)) {
        error = "cannot write " + quotedName(path) + ": it is a directory";
        return false;
    }
    return true;
}

// The module speaks of the file it was given; the caller knows only `path`.
std::string failureOf(const std::string& path, const std::string& temporary,
                      const std::string& problem) {
    return "cannot write " + quotedName(path) + ": " + replaceAll(problem, temporary, path);
}

// Renames the finished temporary over `path` (removing it if that fails).
bool commitTemporary(TemporaryFile& temporary, const std::string& path, std::string& error) {
    std::string why;
    if (temporary.commit(why)) return true;
    error = "cannot write " + quotedName(path) + ": " + why;
    return false;
}

// Runs `write` on a temporary file and renames it over `path`; removes it on any failure.
template <class Write>
bool writeThroughTemporary(const std::string& path, std::string& error, Write&& write) {
    if (!checkTarget(path, error)) return false;
    std::string problem;
    TemporaryFile temporary(path, problem);
    if (temporary.ok() && write(temporary.path(), problem))
        return commitTemporary(temporary, path, error);
    error = failureOf(path, temporary.path(), problem);
    return false;
}

// OpenImageIO's writers do not all report a failed write: on a full disk a GIF was "written"
// as an empty file. So a file the module wrote must read back with the size and number of
// images it was given before it replaces anything.
bool readsBack(const CrtImageIoModule& module, const std::string& file, int width, int height,
               int images, std::string& problem) {
    CrtImageInfo info{};
    CallContext context;
    if (!module.describeImage || !module.describeImage(file.c_str(), &info, acceptsSize, storeError, &context)) {
        // The reader's own words ("no format reader …") would only confuse.
        problem = "the written file does not read back (is the disk full?)";
        return false;
    }
    if (info.width != width || info.height != height || info.subimages != images) {
        problem = "the written file reads back as another image (is the disk full?)";
        return false;
    }
    return true;
}

// The module, or null with "<action>: <why it could not be loaded>" in `error`.
const CrtImageIoModule* moduleFor(const std::string& action, std::string& error) {
    std::string why;
    const CrtImageIoModule* module = detail::loadedModule(why);
    if (!module) error = action + ": " + why;
    return module;
}

} // namespace

bool ensureLoaded(std::string& error) {
    return detail::loadedModule(error) != nullptr;
}

bool isSupportedOutput(const std::string& path) {
    return outputFormatOf(path) != nullptr;
}

bool storesAlpha(const std::string& path) {
    const OutputFormat* format = outputFormatOf(path);
    return format && format->alpha != AlphaStorage::None;
}

void straightenAlpha(std::span<float> rgba) {
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const float alpha = rgba[i + 3];
        if (alpha <= 0) continue; // nothing covers the pixel: its color is black, and stays so
        for (std::size_t c = 0; c < 3; ++c) rgba[i + c] /= alpha;
    }
}

std::optional<ImageBuffer> readImage(const std::string& path, std::string& error, bool* eightBit,
                                     uint64_t maxPixels) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        error = "cannot read " + quotedName(path) + ": no such file";
        return std::nullopt;
    }
    const CrtImageIoModule* module = moduleFor("cannot read " + quotedName(path), error);
    if (!module) return std::nullopt;
    ImageBuffer image;
    CallContext context;
    context.image = &image;
    context.maxPixels = maxPixels;
    int isInteger = 0;
    if (!module->readImage(path.c_str(), &isInteger, acceptsSize, allocatePixels, storeError, &context)) {
        error = "cannot read " + quotedName(path) + ": " + callFailure(context);
        return std::nullopt;
    }
    if (eightBit) *eightBit = isInteger != 0;
    return image;
}

std::unique_ptr<ImageStream> ImageStream::open(const std::string& path, int width, int height,
                                               int channels, const WriteOptions& options,
                                               std::string& error) {
    const OutputFormat* format = outputFormatOf(path);
    if (!format) {
        error = "cannot write " + quotedName(path) + ": unsupported image format \"" +
                lowerExtension(path) + "\"; supported are " + supportedExtensions();
        return nullptr;
    }
    std::string problem;
    if (!checkSize(width, height, channels, problem) || !checkOptions(options, problem)) {
        error = "cannot write " + quotedName(path) + ": " + problem;
        return nullptr;
    }
    if (channels == 4 && format->alpha == AlphaStorage::None) {
        error = "cannot write " + quotedName(path) + ": the format has no alpha channel";
        return nullptr;
    }
    if (!checkTarget(path, error)) return nullptr;
    const CrtImageIoModule* module = format->builtinWriter
                                         ? &format->builtinWriter()
                                         : moduleFor("cannot write " + quotedName(path), error);
    if (!module) return nullptr;

    std::unique_ptr<ImageStream> stream(new ImageStream());
    stream->temporary_ = std::make_unique<TemporaryFile>(path, problem);
    if (!stream->temporary_->ok()) {
        error = "cannot write " + quotedName(path) + ": " + problem;
        return nullptr;
    }
    stream->module_ = module;
    stream->path_ = path;
    stream->width_ = width;
    stream->height_ = height;
    stream->channels_ = channels;
    stream->expandGrey_ = format->needsRgb && channels == 1;
    stream->eightBit_ = format->eightBit;
    stream->premultiply_ = channels == 4 && format->alpha == AlphaStorage::Premultiplied;
    stream->options_ = options;
    CallContext context;
    stream->handle_ = module->openImage(
        stream->temporary_->path().c_str(), format->oiioName, width, height,
        stream->expandGrey_ ? 3 : channels, format->eightBit ? 0 : 1,
        format->eightBit && options.srgb ? 1 : 0, options.pngCompression, storeError, &context);
    if (!stream->handle_) {
        error = failureOf(path, stream->temporary_->path(), context.error);
        return nullptr; // the destructor removes the temporary
    }
    return stream;
}

bool ImageStream::writeRows(int yBegin, int yEnd, std::span<const float> values,
                            std::string& error) {
    const std::size_t expected =
        std::size_t(yEnd - yBegin) * std::size_t(width_) * std::size_t(channels_);
    if (!handle_ || yBegin != nextRow_ || yEnd <= yBegin || yEnd > height_ ||
        values.size() != expected) {
        error = "cannot write " + quotedName(path_) + ": rows " + std::to_string(yBegin) + " to " +
                std::to_string(yEnd) + " do not follow row " + std::to_string(nextRow_) + " with " +
                std::to_string(expected) + " values";
        return false;
    }
    const int fileChannels = expandGrey_ ? 3 : channels_;
    std::vector<float> converted;
    if (expandGrey_) converted = expandGrey(values);
    if (premultiply_) {
        converted.assign(values.begin(), values.end());
        for (std::size_t i = 0; i + 3 < converted.size(); i += 4)
            for (std::size_t c = 0; c < 3; ++c) converted[i + c] *= converted[i + 3];
    }
    const std::span<const float> stored = expandGrey_ || premultiply_ ? converted : values;
    std::vector<std::uint8_t> codes;
    if (eightBit_) codes = quantiseColor(stored, fileChannels, options_);
    const void* pixels = eightBit_ ? static_cast<const void*>(codes.data())
                                   : static_cast<const void*>(stored.data());
    CallContext context;
    if (!module_->writeRows(handle_, yBegin, yEnd, pixels, storeError, &context)) {
        error = failureOf(path_, temporary_->path(), context.error);
        return false;
    }
    nextRow_ = yEnd;
    return true;
}

bool ImageStream::finish(std::string& error) {
    if (!handle_ || nextRow_ != height_) {
        error = "cannot write " + quotedName(path_) + ": only " + std::to_string(nextRow_) +
                " of " + std::to_string(height_) + " rows were written";
        return false;
    }
    CallContext context;
    const int closed = module_->closeImage(handle_, 0, storeError, &context);
    handle_ = nullptr;
    std::string problem = context.error;
    // The built-in PNG writer checks every write itself, and has no reader.
    if (!closed || (module_->describeImage &&
                    !readsBack(*module_, temporary_->path(), width_, height_, 1, problem))) {
        error = failureOf(path_, temporary_->path(), problem);
        return false; // the destructor removes the temporary
    }
    return commitTemporary(*temporary_, path_, error);
}

ImageStream::~ImageStream() {
    if (handle_) {
        CallContext ignored;
        module_->closeImage(handle_, 1, storeError, &ignored);
    }
    // temporary_, unless committed, removes its file.
}

bool writeImage(const std::string& path, const ImageBuffer& image, const WriteOptions& options,
                std::string& error) {
    std::string problem;
    if (isSupportedOutput(path) && !checkBuffer(image, problem)) {
        error = "cannot write " + quotedName(path) + ": " + problem;
        return false;
    }
    std::unique_ptr<ImageStream> stream =
        ImageStream::open(path, image.width, image.height, image.channels, options, error);
    return stream && stream->writeRows(0, image.height, image.pixels, error) &&
           stream->finish(error);
}

bool copyImage(const std::string& from, const std::string& to, std::string& error) {
    return writeThroughTemporary(to, error, [&](const std::string& temporary, std::string& why) {
        std::error_code ec;
        fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
        if (ec) why = "cannot copy " + quotedName(from) + ": " + ec.message();
        return !ec;
    });
}

bool GifFrames::add(const ImageBuffer& frame, const WriteOptions& options, std::string& problem) {
    const std::string which = "frame " + std::to_string(frames_.size());
    if (!checkOptions(options, problem) || !checkBuffer(frame, problem)) {
        problem = which + ": " + problem;
        return false;
    }
    // GIF stores color: a grey frame becomes three equal channels.
    const int channels = frame.channels == 1 ? 3 : frame.channels;
    if (!frames_.empty() &&
        (frame.width != width_ || frame.height != height_ || channels != channels_)) {
        problem = which + " differs in size from frame 0";
        return false;
    }
    width_ = frame.width;
    height_ = frame.height;
    channels_ = channels;
    frames_.push_back(std::make_shared<const std::vector<std::uint8_t>>(
        frame.channels == 1 ? quantiseColor(expandGrey(frame.pixels), 3, options)
                            : quantiseColor(frame.pixels, frame.channels, options)));
    return true;
}

void GifFrames::repeatLast() {
    frames_.push_back(frames_.back());
}

std::vector<const std::uint8_t*> GifFrames::framePointers() const {
    std::vector<const std::uint8_t*> pointers;
    pointers.reserve(frames_.size());
    for (const auto& codes : frames_) pointers.push_back(codes->data());
    return pointers;
}

namespace {

/// Why an animation cannot be written to `path` at `fps` (before looking at its frames).
std::string animationProblem(const std::string& path, std::size_t frameCount, double fps) {
    if (lowerExtension(path) != ".gif")
        return "an animation is written as a GIF, so the name must end in .gif";
    if (frameCount == 0) return "an animation needs at least one frame";
    if (!(fps > 0.0) || !std::isfinite(fps)) return "the frame rate must be a positive number";
    return {};
}

} // namespace

bool writeAnimatedGif(const std::string& path, const GifFrames& frames, double fps,
                      std::string& error) {
    if (std::string problem = animationProblem(path, frames.size(), fps); !problem.empty()) {
        error = "cannot write " + quotedName(path) + ": " + problem;
        return false;
    }
    const CrtImageIoModule* module = moduleFor("cannot write " + quotedName(path), error);
    if (!module) return false;
    const std::vector<const std::uint8_t*> framePointers = frames.framePointers();
    // OIIO gives every frame the same delay (here 1/100 s); each frame's own, which keep the
    // rate, are set in the file after.
    const std::vector<std::uint16_t> delays = gifFrameDelays(int(frames.size()), fps);
    return writeThroughTemporary(path, error, [&](const std::string& temporary, std::string& why) {
        CallContext context;
        const int ok = module->writeAnimatedGif(temporary.c_str(), frames.width(), frames.height(),
                                                frames.channels(), int(frames.size()),
                                                framePointers.data(), 100, 1, storeError, &context);
        why = context.error;
        return ok != 0 && writeGifDelays(temporary, delays, why) &&
               readsBack(*module, temporary, frames.width(), frames.height(), int(frames.size()),
                         why);
    });
}

bool writeAnimatedGif(const std::string& path, const std::vector<ImageBuffer>& frames, double fps,
                      const WriteOptions& options, std::string& error) {
    std::string problem = animationProblem(path, frames.size(), fps);
    GifFrames codes;
    for (std::size_t i = 0; i < frames.size() && problem.empty(); ++i) {
        if (!codes.add(frames[i], options, problem)) break;
    }
    if (!problem.empty()) {
        error = "cannot write " + quotedName(path) + ": " + problem;
        return false;
    }
    return writeAnimatedGif(path, codes, fps, error);
}

std::optional<ImageInfo> describeImage(const std::string& path, std::string& error, uint64_t maxPixels) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        error = "cannot read " + quotedName(path) + ": no such file";
        return std::nullopt;
    }
    const CrtImageIoModule* module = moduleFor("cannot read " + quotedName(path), error);
    if (!module) return std::nullopt;
    CrtImageInfo raw{};
    CallContext context;
    context.maxPixels = maxPixels;
    if (!module->describeImage(path.c_str(), &raw, acceptsSize, storeError, &context)) {
        error = "cannot read " + quotedName(path) + ": " + callFailure(context);
        return std::nullopt;
    }
    ImageInfo info;
    info.width = raw.width;
    info.height = raw.height;
    info.channels = raw.channels;
    info.subimages = raw.subimages;
    info.integer = raw.isInteger != 0;
    info.fps = raw.fpsDenominator != 0 ? double(raw.fpsNumerator) / raw.fpsDenominator : 0.0;
    info.loopCount = raw.loopCount;
    info.format = std::string(raw.format, ::strnlen(raw.format, sizeof raw.format));
    return info;
}

} // namespace crt::tracer::image_io
