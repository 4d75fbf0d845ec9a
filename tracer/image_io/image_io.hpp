// Image input and output for the renderer, through OpenImageIO loaded as a module on first use.
//
// Linking this library costs nothing at start: OpenImageIO (about 260 shared libraries on
// Debian, slow to load and large in memory) lives in crt_image_io_oiio.so, which the first
// call that needs it dlopens, once per process. The module is looked for next to the running
// executable, then in <exe dir>/../lib/crt/; the environment variable CRT_IMAGE_IO_MODULE
// names it explicitly. PNG, the default output, is written with libpng and never loads the
// module (png_writer.hpp). All functions are thread-safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

struct CrtImageIoModule;

namespace crt::tracer::image_io {

class TemporaryFile;

/// Row-major, top row first, `channels` floats per pixel (3 = RGB).
struct ImageBuffer {
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<float> pixels;
};

/// How writeImage turns linear values into 8-bit codes; EXR and HDR ignore it.
struct WriteOptions {
    double gamma = 1.0; ///< must be > 0
    bool srgb = false;  ///< the IEC 61966-2-1 sRGB encoding instead of the gamma power
    /// zlib level of a PNG, 0 (none) to 9 (smallest). The default is below zlib's own 6:
    /// on rendered images the higher levels cost much more time than they save in size.
    int pngCompression = kDefaultPngCompression;
    static constexpr int kDefaultPngCompression = 2;
};

/// Loads the module now unless it is loaded (or its load failed) already; false with a message
/// if it cannot be loaded. Lets a driver fail before a long render rather than after it.
bool ensureLoaded(std::string& error);

/// Reads any format OIIO reads into linear-ready floats: 8-bit (and other integer) formats come
/// back as raw value / max (the caller decides about sRGB decoding), float formats as stored.
/// Always returns 3 channels (grey replicated, alpha dropped). `eightBit` (optional) tells
/// whether the source was an integer format. On failure, `error` names the path and the cause.
/// An image of more than `maxPixels` pixels (width × height as its header says) is refused
/// before any of its pixels is read or room is made for them, and for some formats before
/// OpenImageIO opens the file (their readers reserve memory for the claimed size there); so is
/// one of more than four channels that holds more values than `maxPixels` pixels of four.
std::optional<ImageBuffer> readImage(const std::string& path, std::string& error,
                                     bool* eightBit = nullptr,
                                     uint64_t maxPixels = std::numeric_limits<uint64_t>::max());

/// Writes by extension (case-insensitive): .png, .jpg/.jpeg, .tif/.tiff, .gif (one frame) in
/// 8 bits, .exr and .hdr in floats; any other extension is an error that lists these.
/// 8-bit formats store ⌊255 · clamp(c, 0, 1)^(1/gamma) + ½⌋ per channel, or the sRGB encoding
/// when `options.srgb`; EXR and HDR store the linear values unclamped. `image.channels` may be
/// 1, 3 or 4 where the format allows it; a fourth channel is straight (not premultiplied) alpha,
/// quantised without the gamma (OpenEXR, whose convention is premultiplied alpha, gets the
/// color multiplied by it). The image goes to a temporary file in the same
/// directory (temporary_file.hpp: a random name, created exclusively) that is renamed into
/// place once it is complete: flushed to the disk, not empty, and, when OpenImageIO wrote it,
/// read back with the expected size. So a failed or interrupted write never leaves a partial
/// file under `path`, nor replaces the previous one; the temporary is removed on failure.
bool writeImage(const std::string& path, const ImageBuffer& image, const WriteOptions& options,
                std::string& error);

/// An image written band by band, top to bottom, as its rows become final (a render streams
/// finished rows while later ones are traced, so that encoding overlaps tracing); same
/// formats, quantisation and temporary-file rule as writeImage. Destroying a stream that was
/// not finished removes its temporary file, so an interrupted render leaves nothing.
class ImageStream {
  public:
    /// Checks the name, size and options and opens the temporary file (loading the module
    /// unless the format is PNG); null with a message in `error` on failure.
    static std::unique_ptr<ImageStream> open(const std::string& path, int width, int height,
                                             int channels, const WriteOptions& options,
                                             std::string& error);
    /// Rows [yBegin, yEnd), which must follow the rows written before: `channels` floats per
    /// pixel, row-major.
    bool writeRows(int yBegin, int yEnd, std::span<const float> values, std::string& error);
    /// After the last row: completes the file and renames it into place.
    bool finish(std::string& error);

    ImageStream(const ImageStream&) = delete;
    ImageStream& operator=(const ImageStream&) = delete;
    ~ImageStream();

  private:
    ImageStream() = default;

    const CrtImageIoModule* module_ = nullptr;
    void* handle_ = nullptr;
    std::string path_;
    std::unique_ptr<TemporaryFile> temporary_;
    int width_ = 0, height_ = 0, channels_ = 3;
    bool expandGrey_ = false, eightBit_ = true;
    bool premultiply_ = false; ///< OpenEXR: the color is stored multiplied by alpha
    WriteOptions options_;
    int nextRow_ = 0;
};

/// The frames of an animated GIF as they are made, kept as the 8-bit codes the file stores:
/// 3 bytes an RGB pixel instead of the 12 of a float frame, and nothing more for a frame that
/// repeats the one before. A long animation then fits in memory.
class GifFrames {
  public:
    /// Quantises `frame` with `options` (as writeImage would) and keeps it; false, with the
    /// problem in `problem`, for a malformed frame or one of another size than the first.
    bool add(const ImageBuffer& frame, const WriteOptions& options, std::string& problem);
    /// Keeps the last frame once more (there must be one).
    void repeatLast();
    std::size_t size() const { return frames_.size(); }
    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; } ///< 3 (RGB) or 4 (RGBA)
    /// Each frame's codes, row-major from the top.
    std::vector<const std::uint8_t*> framePointers() const;

  private:
    int width_ = 0;
    int height_ = 0;
    int channels_ = 3;
    std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> frames_; ///< repeats share
};

/// Writes an animated GIF (`path` must end in .gif): one subimage per frame, `fps` frames per
/// second, looping forever, through a temporary file as writeImage. GIF stores a delay in
/// hundredths of a second, so the rate is rounded to 100/n.
bool writeAnimatedGif(const std::string& path, const GifFrames& frames, double fps,
                      std::string& error);

/// The same from float frames, all of one size, each quantised with `options`.
bool writeAnimatedGif(const std::string& path, const std::vector<ImageBuffer>& frames, double fps,
                      const WriteOptions& options, std::string& error);

/// Copies the image file `from` to `to` (an unchanged frame of a numbered sequence), through
/// a temporary file renamed into place like every write; false with a message on failure.
bool copyImage(const std::string& from, const std::string& to, std::string& error);

/// Whether the extension names a format writeImage supports.
bool isSupportedOutput(const std::string& path);
/// Whether that format keeps a fourth channel, alpha (PNG, TIFF, OpenEXR); writing four
/// channels to another format is an error.
bool storesAlpha(const std::string& path);
/// Turns premultiplied RGBA (as a renderer's coverage makes it) into the straight alpha the
/// writers take: the color divided by alpha where alpha is above 0.
void straightenAlpha(std::span<float> rgba);

/// What a file's header says, as OpenImageIO reads it.
struct ImageInfo {
    int width = 0;
    int height = 0;
    int channels = 0;     ///< as stored (a GIF reads as 4: RGBA)
    int subimages = 0;    ///< frames of an animation
    bool integer = false; ///< an integer pixel format such as uint8
    double fps = 0;       ///< FramesPerSecond, 0 when absent
    int loopCount = -1;   ///< -1 when absent, 0 = forever
    std::string format;   ///< OpenImageIO's format name, e.g. "png", "openexr"
};

/// Reads the header of an image file (subimage count, frame rate …), for tests and tools;
/// an image of more than `maxPixels` pixels is refused as readImage refuses it.
std::optional<ImageInfo> describeImage(const std::string& path, std::string& error,
                                       uint64_t maxPixels = std::numeric_limits<uint64_t>::max());

} // namespace crt::tracer::image_io
