// Reading and writing images through the OpenImageIO module, in one coarse process.
//
// Registered as a single CTest test (not per Catch2 case), since every process that loads
// the module pays OpenImageIO's slow start. CRT_IMAGE_IO_MODULE names the built module.
// Cases run in declaration order; the first one must see the module still unloaded.
#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/gif_frame_delays.hpp"
#include "tracer/image_io/image_io.hpp"

#include "../scratch_folder.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <thread>
#include <vector>

using namespace crt::tracer::image_io;
namespace fs = std::filesystem;

namespace {

using namespace crt::tracer::test;

// An RGB image whose every value is a multiple of 1/255, so 8-bit formats store it exactly.
ImageBuffer codeGradient(int width, int height) {
    ImageBuffer image{width, height, 3, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            image.pixels.push_back(float((x * 7 + y * 3) % 256) / 255.0f);
            image.pixels.push_back(float((x * 13) % 256) / 255.0f);
            image.pixels.push_back(float((y * 11 + 5) % 256) / 255.0f);
        }
    return image;
}

ImageBuffer solid(int width, int height, float r, float g, float b) {
    ImageBuffer image{width, height, 3, {}};
    for (int i = 0; i < width * height; ++i) image.pixels.insert(image.pixels.end(), {r, g, b});
    return image;
}

ImageBuffer readOrFail(const std::string& path, bool* eightBit = nullptr) {
    std::string error;
    std::optional<ImageBuffer> image = readImage(path, error, eightBit);
    INFO(error);
    REQUIRE(image);
    REQUIRE((image->channels == 3 || image->channels == 4));
    REQUIRE(image->pixels.size() == std::size_t(image->width) * image->height * image->channels);
    return *image;
}

void writeOrFail(const std::string& path, const ImageBuffer& image,
                 const WriteOptions& options = {}) {
    std::string error;
    const bool ok = writeImage(path, image, options, error);
    INFO(error);
    REQUIRE(ok);
}

// A binary PPM written by hand, readable without having written anything through OIIO.
void writePpm(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << width << " " << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
}

// A little-endian TIFF of 8-bit values, `channels` a pixel, in strips of `rowsPerStrip` rows
// deflated by zlib, written by hand: OpenImageIO writes neither min-is-white files (code 0 is
// white) nor files of hundreds of channels. The channels past the colour (grey, or RGB when
// not min-is-white) are extra samples, the first of them unassociated alpha.
std::string deflatedTiff(int width, int height, int channels, bool minIsWhite,
                         std::uint32_t rowsPerStrip, const std::vector<std::uint8_t>& values) {
    std::string file = "II*";
    auto put16 = [&](std::uint32_t v) { file += {char(v), char(v >> 8)}; };
    auto put32 = [&](std::uint32_t v) { put16(v & 0xffff), put16(v >> 16); };
    put16(0), put32(0); // the directory's offset, set below
    std::vector<std::uint32_t> offsets, sizes;
    const std::size_t rowBytes = std::size_t(width) * channels;
    for (std::int64_t y = 0; y < height; y += rowsPerStrip) {
        const std::size_t bytes =
            std::size_t(std::min<std::int64_t>(rowsPerStrip, height - y)) * rowBytes;
        std::vector<Bytef> strip(compressBound(uLong(bytes)));
        uLongf size = uLongf(strip.size());
        REQUIRE(compress(strip.data(), &size, &values[std::size_t(y) * rowBytes], uLong(bytes)) ==
                Z_OK);
        offsets.push_back(std::uint32_t(file.size()));
        sizes.push_back(std::uint32_t(size));
        file.append(reinterpret_cast<const char*>(strip.data()), size);
    }
    // A field's values are in its directory entry when they fit in 4 bytes, elsewhere otherwise.
    auto field = [&](const auto& values) -> std::uint32_t {
        constexpr std::size_t kSize = sizeof(values[0]);
        if (values.empty()) return 0;
        if (values.size() * kSize <= 4)
            return values.size() == 1 ? values[0] : values[0] | values[1] << 16;
        if (file.size() % 2) file += '\0';
        const auto at = std::uint32_t(file.size());
        for (auto v : values) kSize == 2 ? put16(v) : put32(v);
        return at;
    };
    const int colours = minIsWhite ? 1 : 3;
    std::vector<std::uint16_t> extraSamples(std::size_t(channels - colours), 0);
    if (!extraSamples.empty()) extraSamples[0] = 2;
    const std::uint32_t bitsField = field(std::vector<std::uint16_t>(std::size_t(channels), 8));
    const std::uint32_t extraField = field(extraSamples);
    const std::uint32_t offsetsField = field(offsets), sizesField = field(sizes);
    if (file.size() % 2) file += '\0';
    const auto directoryAt = std::uint32_t(file.size());
    for (int i = 0; i < 4; ++i) file[4 + i] = char(directoryAt >> 8 * i);
    enum : std::uint16_t { kShort = 3, kLong = 4 };
    auto entry = [&](std::uint16_t tag, std::uint16_t type, std::size_t count,
                     std::uint32_t value) {
        put16(tag), put16(type), put32(std::uint32_t(count)), put32(value);
    };
    put16(extraSamples.empty() ? 9 : 10);
    entry(256, kShort, 1, width);                    // ImageWidth
    entry(257, kShort, 1, height);                   // ImageLength
    entry(258, kShort, channels, bitsField);         // BitsPerSample
    entry(259, kShort, 1, 8);                        // Compression: deflate
    entry(262, kShort, 1, minIsWhite ? 0 : 2);       // PhotometricInterpretation
    entry(273, kLong, offsets.size(), offsetsField); // StripOffsets
    entry(277, kShort, 1, channels);                 // SamplesPerPixel
    entry(278, kLong, 1, rowsPerStrip);              // RowsPerStrip
    entry(279, kLong, sizes.size(), sizesField);     // StripByteCounts
    if (!extraSamples.empty()) entry(338, kShort, extraSamples.size(), extraField); // ExtraSamples
    put32(0);
    return file;
}

} // namespace

TEST_CASE("concurrent first reads from many threads, racing to load the module", "[image_io]") {
    // Written by hand, so that the readers below are the module's first users and race to
    // load it: every one must wait for the load and then read correctly.
    const int width = 17, height = 9;
    std::vector<std::uint8_t> rgb;
    for (int i = 0; i < width * height * 3; ++i) rgb.push_back(std::uint8_t((i * 37) % 256));
    const std::string ppm = scratchFile("concurrent.ppm");
    writePpm(ppm, width, height, rgb);

    CHECK_FALSE(openImageIoMapped());
    constexpr int kThreads = 8, kReadsPerThread = 10;
    std::vector<int> failures(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int n = 0; n < kReadsPerThread; ++n) {
                std::string error;
                bool eightBit = false;
                const std::optional<ImageBuffer> image = readImage(ppm, error, &eightBit);
                bool same = image && eightBit && image->width == width && image->height == height &&
                            image->pixels.size() == rgb.size();
                for (std::size_t i = 0; same && i < rgb.size(); ++i)
                    same = image->pixels[i] == float(rgb[i]) / 255.0f;
                if (!same) ++failures[t];
            }
        });
    for (std::thread& thread : threads) thread.join();
    for (int t = 0; t < kThreads; ++t) CHECK(failures[t] == 0);
    std::string error;
    CHECK(ensureLoaded(error));
    CHECK(openImageIoMapped());
}

TEST_CASE("PNG and TIFF round trips are exact for 8-bit codes", "[image_io]") {
    const ImageBuffer image = codeGradient(64, 40);
    for (const char* name : {"round.png", "round.tif", "round.tiff", "ROUND.PNG"}) {
        INFO(name);
        writeOrFail(scratchFile(name), image);
        bool eightBit = false;
        const ImageBuffer back = readOrFail(scratchFile(name), &eightBit);
        CHECK(eightBit);
        CHECK(back.width == image.width);
        CHECK(back.height == image.height);
        CHECK(back.pixels == image.pixels);
    }
}

TEST_CASE("8-bit files hold the spec's codes", "[image_io]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // One row: 0, 1, ½, negative, NaN, above 1, ¼, a tiny value.
    const std::vector<float> values{0.0f, 1.0f, 0.5f, -0.3f, nan, 4.0f, 0.25f, 0.001f};
    ImageBuffer image{int(values.size()), 1, 3, {}};
    for (float v : values) image.pixels.insert(image.pixels.end(), {v, v, v});

    struct Case {
        WriteOptions options;
        std::vector<int> codes;
    };
    const Case cases[] = {
        {{1.0, false}, {0, 255, 128, 0, 0, 255, 64, 0}},
        {{2.2, false}, {0, 255, 186, 0, 0, 255, 136, 11}},
        {{1.0, true}, {0, 255, 188, 0, 0, 255, 137, 3}},
    };
    for (const Case& c : cases) {
        INFO("gamma " << c.options.gamma << " srgb " << c.options.srgb);
        const std::string path = scratchFile("codes.png");
        writeOrFail(path, image, c.options);
        const ImageBuffer back = readOrFail(path);
        for (std::size_t i = 0; i < values.size(); ++i) {
            INFO("value " << values[i]);
            const int expected =
                c.options.srgb ? encodeSrgb8(values[i]) : encodeGamma8(values[i], c.options.gamma);
            CHECK(expected == c.codes[i]);
            for (int ch = 0; ch < 3; ++ch) CHECK(back.pixels[i * 3 + ch] == c.codes[i] / 255.0f);
        }
    }
}

TEST_CASE("EXR keeps linear values, above 1 and negative, exactly", "[image_io]") {
    ImageBuffer image{4, 2, 3, {}};
    const float values[] = {0.0f, 1.0f, 3.5f, -0.25f, 1e4f, 1e-6f, 0.1f, -7.0f};
    for (int i = 0; i < 8; ++i)
        image.pixels.insert(image.pixels.end(), {values[i], values[i] * 2.0f, -values[i]});
    const std::string path = scratchFile("linear.exr");
    // Options are for 8-bit formats only: a gamma must not touch float output.
    writeOrFail(path, image, {2.2, true});
    bool eightBit = true;
    const ImageBuffer back = readOrFail(path, &eightBit);
    CHECK_FALSE(eightBit);
    CHECK(back.width == 4);
    CHECK(back.height == 2);
    CHECK(back.pixels == image.pixels);
}

TEST_CASE("HDR keeps values above 1 within RGBE precision", "[image_io]") {
    ImageBuffer image{3,
                      2,
                      3,
                      {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 5.0f, 2.5f, 0.5f, 100.0f, 0.0f, 30.0f,
                       0.25f, 0.125f, 0.0625f, 0.7f, 0.3f, 0.9f}};
    const std::string path = scratchFile("radiance.hdr");
    writeOrFail(path, image);
    bool eightBit = true;
    const ImageBuffer back = readOrFail(path, &eightBit);
    CHECK_FALSE(eightBit);
    REQUIRE(back.pixels.size() == image.pixels.size());
    for (std::size_t p = 0; p < image.pixels.size(); p += 3) {
        // RGBE shares one exponent per pixel: the error is relative to the largest channel.
        const float largest = std::max({image.pixels[p], image.pixels[p + 1], image.pixels[p + 2]});
        for (int ch = 0; ch < 3; ++ch)
            CHECK(back.pixels[p + ch] == Approx(image.pixels[p + ch]).margin(largest / 128.0f));
    }
}

TEST_CASE("JPEG round trip stays within a tolerance", "[image_io]") {
    ImageBuffer image{64, 48, 3, {}};
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            image.pixels.insert(image.pixels.end(), {x / 63.0f, y / 47.0f,
                                                     0.5f + 0.3f * std::sin(x * 0.1f + y * 0.05f)});
    for (const char* name : {"photo.jpg", "photo.jpeg"}) {
        writeOrFail(scratchFile(name), image);
        bool eightBit = false;
        const ImageBuffer back = readOrFail(scratchFile(name), &eightBit);
        CHECK(eightBit);
        REQUIRE(back.pixels.size() == image.pixels.size());
        double sum = 0, worst = 0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            const double d = std::abs(back.pixels[i] - image.pixels[i]);
            sum += d;
            worst = std::max(worst, d);
        }
        CHECK(sum / image.pixels.size() < 2.0 / 255.0);
        CHECK(worst < 12.0 / 255.0);
    }
}

TEST_CASE("grey images read as three equal channels", "[image_io]") {
    ImageBuffer grey{5, 3, 1, {}};
    for (int i = 0; i < 15; ++i) grey.pixels.push_back(float(i * 17) / 255.0f);
    for (const char* name : {"grey.png", "grey.exr", "grey.gif", "grey.hdr"}) {
        INFO(name);
        writeOrFail(scratchFile(name), grey);
        const ImageBuffer back = readOrFail(scratchFile(name));
        REQUIRE(back.pixels.size() == 45);
        for (int i = 0; i < 15; ++i) {
            CHECK(back.pixels[i * 3] == back.pixels[i * 3 + 1]);
            CHECK(back.pixels[i * 3] == back.pixels[i * 3 + 2]);
        }
        if (std::string(name) == "grey.png" || std::string(name) == "grey.exr")
            for (int i = 0; i < 15; ++i) CHECK(back.pixels[i * 3] == grey.pixels[i]);
    }
    // A PGM written by hand: an 8-bit single-channel file from elsewhere.
    const std::string pgm = scratchFile("hand.pgm");
    {
        std::ofstream out(pgm, std::ios::binary);
        out << "P5\n2 1\n255\n";
        out.put(char(10)).put(char(200));
    }
    const ImageBuffer back = readOrFail(pgm);
    CHECK(back.pixels == std::vector<float>{10 / 255.0f, 10 / 255.0f, 10 / 255.0f, 200 / 255.0f,
                                            200 / 255.0f, 200 / 255.0f});
}

TEST_CASE("alpha is read beside the colour, which is not premultiplied", "[image_io]") {
    ImageBuffer rgba{2, 1, 4, {0.6f, 0.4f, 0.2f, 0.0f, 1.0f, 0.5f, 0.0f, 0.5f}};
    const std::string path = scratchFile("alpha.png");
    writeOrFail(path, rgba, {2.2, false});
    const ImageBuffer back = readOrFail(path);
    REQUIRE(back.channels == 4);
    CHECK(back.pixels[0] == encodeGamma8(0.6f, 2.2) / 255.0f); // alpha 0 keeps its colour
    CHECK(back.pixels[1] == encodeGamma8(0.4f, 2.2) / 255.0f);
    CHECK(back.pixels[3] == 0.0f);
    CHECK(back.pixels[4] == 1.0f);
    CHECK(back.pixels[5] == encodeGamma8(0.5f, 2.2) / 255.0f); // not multiplied by alpha ½
    CHECK(back.pixels[7] == Approx(0.5).margin(1 / 255.0));    // alpha is not gamma-encoded
    ImageBuffer rgb{2, 1, 3, {0.6f, 0.4f, 0.2f, 1.0f, 0.5f, 0.0f}};
    writeOrFail(scratchFile("opaque.png"), rgb);
    CHECK(readOrFail(scratchFile("opaque.png")).channels == 3);
    std::string error;
    const std::optional<ImageInfo> info = describeImage(path, error);
    REQUIRE(info);
    CHECK(info->channels == 4);
}

TEST_CASE("GIF frames are kept as 8-bit codes, and a repeated frame shares the one before",
          "[image_io]") {
    GifFrames frames;
    std::string problem;
    REQUIRE(frames.add(solid(16, 12, 0.0f, 1.0f, 0.0f), {}, problem));
    frames.repeatLast();
    REQUIRE(frames.add(solid(16, 12, 1.0f, 0.0f, 0.0f), {}, problem));
    REQUIRE(frames.size() == 3);
    CHECK(frames.channels() == 3);
    const std::vector<const std::uint8_t*> codes = frames.framePointers();
    CHECK(codes[1] == codes[0]); // the repeat holds no copy
    CHECK(codes[2] != codes[0]);
    CHECK((codes[0][0] == 0 && codes[0][1] == 255 && codes[0][2] == 0));
    CHECK((codes[2][0] == 255 && codes[2][1] == 0 && codes[2][2] == 0));
    // Each frame is quantised with its own options: ½ is 128 linear, 186 through gamma 2.2.
    REQUIRE(frames.add(solid(16, 12, 0.5f, 0.5f, 0.5f), {2.2, false}, problem));
    CHECK(frames.framePointers()[3][0] == encodeGamma8(0.5f, 2.2));
    CHECK_FALSE(frames.add(solid(8, 8, 0, 0, 0), {}, problem));
    CHECK_THAT(problem, Catch::Contains("frame 4 differs in size"));
    CHECK_FALSE(frames.add(solid(16, 12, 0, 0, 0), {0.0, false}, problem));
    CHECK_THAT(problem, Catch::Contains("gamma"));
    CHECK(frames.size() == 4); // the refused frames were not kept

    const std::string path = scratchFile("codes.gif");
    std::string error;
    REQUIRE(writeAnimatedGif(path, frames, 10.0, error));
    const std::optional<ImageInfo> info = describeImage(path, error);
    INFO(error);
    REQUIRE(info);
    CHECK(info->subimages == 4);
    CHECK(info->width == 16);
    CHECK_FALSE(writeAnimatedGif(scratchFile("none.gif"), GifFrames{}, 10.0, error));
    CHECK_THAT(error, Catch::Contains("at least one frame"));
}

TEST_CASE("an animated GIF has one subimage per frame, the frame rate, and loops", "[image_io]") {
    std::vector<ImageBuffer> frames;
    for (int i = 0; i < 5; ++i) frames.push_back(solid(16, 12, i / 4.0f, 1.0f - i / 4.0f, 0.0f));
    const std::string path = scratchFile("anim.gif");
    std::string error;
    REQUIRE(writeAnimatedGif(path, frames, 20.0, {}, error));
    std::optional<ImageInfo> info = describeImage(path, error);
    INFO(error);
    REQUIRE(info);
    CHECK(info->format == "gif");
    CHECK(info->subimages == 5);
    CHECK(info->width == 16);
    CHECK(info->height == 12);
    CHECK(info->fps == Approx(20.0));
    CHECK(info->loopCount == 0);
    // The first frame is pure green, which a 256-colour palette holds exactly.
    const ImageBuffer first = readOrFail(path);
    CHECK(first.pixels[0] == 0.0f);
    CHECK(first.pixels[1] == 1.0f);
    CHECK(first.pixels[2] == 0.0f);

    // GIF keeps delays in hundredths of a second: at 15 fps the frames alternate 7, 6 and 7
    // hundredths, so that every third frame ends on the time the rate puts it at.
    REQUIRE(writeAnimatedGif(path, frames, 15.0, {}, error));
    std::optional<std::vector<std::uint16_t>> delays = readGifDelays(path, error);
    INFO(error);
    REQUIRE(delays);
    CHECK(*delays == std::vector<std::uint16_t>{7, 6, 7, 7, 6});
    REQUIRE(writeAnimatedGif(path, frames, 20.0, {}, error));
    delays = readGifDelays(path, error);
    REQUIRE(delays);
    CHECK(*delays == std::vector<std::uint16_t>{5, 5, 5, 5, 5});

    CHECK(writeAnimatedGif(scratchFile("one.gif"), {frames[0]}, 10.0, {}, error));
    CHECK_FALSE(writeAnimatedGif(scratchFile("anim.png"), frames, 20.0, {}, error));
    CHECK_THAT(error, Catch::Contains(".gif"));
    CHECK_FALSE(writeAnimatedGif(scratchFile("bad.gif"), {frames[0], solid(8, 8, 0, 0, 0)}, 20.0,
                                 {}, error));
    CHECK_THAT(error, Catch::Contains("frame 1"));
    CHECK_FALSE(writeAnimatedGif(scratchFile("bad.gif"), frames, 0.0, {}, error));
    CHECK_FALSE(writeAnimatedGif(scratchFile("bad.gif"), {}, 20.0, {}, error));
    CHECK_FALSE(fs::exists(scratchFile("bad.gif")));
}

TEST_CASE("a single-frame GIF is written by extension", "[image_io]") {
    const std::string path = scratchFile("still.gif");
    writeOrFail(path, solid(8, 8, 1.0f, 0.0f, 0.0f));
    std::string error;
    const std::optional<ImageInfo> info = describeImage(path, error);
    REQUIRE(info);
    CHECK(info->subimages == 1);
    const ImageBuffer back = readOrFail(path);
    CHECK(back.pixels[0] == 1.0f);
    CHECK(back.pixels[1] == 0.0f);
}

TEST_CASE("a write into a missing directory fails and leaves nothing", "[image_io]") {
    const std::string path = scratchFile("no_such_dir/out.png");
    std::string error;
    CHECK_FALSE(writeImage(path, solid(4, 4, 0.5f, 0.5f, 0.5f), {}, error));
    CHECK_THAT(error, Catch::Contains(path) && Catch::Contains("does not exist"));
    CHECK_FALSE(fs::exists(scratchFile("no_such_dir")));
}

TEST_CASE("no temporary file stays after a write, failed or not", "[image_io]") {
    const fs::path dir = scratch() / "tidy";
    fs::create_directories(dir);
    const ImageBuffer image = solid(8, 8, 0.2f, 0.4f, 0.6f);
    std::string error;
    for (const char* name : {"a.png", "b.jpg", "c.tif", "d.exr", "e.hdr", "f.gif"})
        CHECK(writeImage((dir / name).string(), image, {}, error));
    // Overwriting an existing image replaces it whole.
    CHECK(writeImage((dir / "a.png").string(), solid(3, 2, 1.0f, 1.0f, 1.0f), {}, error));
    CHECK(readOrFail((dir / "a.png").string()).width == 3);
    // Failures after the temporary file exists: a format that cannot take the channel count,
    // and a rename onto a directory.
    ImageBuffer rgba{2, 2, 4, std::vector<float>(16, 0.5f)};
    CHECK_FALSE(writeImage((dir / "g.hdr").string(), rgba, {}, error));
    fs::create_directory(dir / "h.png");
    CHECK_FALSE(writeImage((dir / "h.png").string(), image, {}, error));
    CHECK_THAT(error, Catch::Contains("directory"));

    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    CHECK(names ==
          std::vector<std::string>{"a.png", "b.jpg", "c.tif", "d.exr", "e.hdr", "f.gif", "h.png"});
}

TEST_CASE("bad buffers and options are errors", "[image_io]") {
    std::string error;
    const std::string path = scratchFile("bad.png");
    CHECK_FALSE(writeImage(path, ImageBuffer{2, 2, 3, std::vector<float>(5)}, {}, error));
    CHECK_THAT(error, Catch::Contains("values"));
    CHECK_FALSE(writeImage(path, ImageBuffer{0, 2, 3, {}}, {}, error));
    CHECK_FALSE(writeImage(path, ImageBuffer{1, 1, 2, {0, 0}}, {}, error));
    CHECK_FALSE(writeImage(path, solid(1, 1, 0, 0, 0), {0.0, false}, error));
    CHECK_THAT(error, Catch::Contains("gamma"));
    CHECK_FALSE(writeImage(path, solid(1, 1, 0, 0, 0), {std::nan(""), false}, error));
    CHECK_FALSE(fs::exists(path));
}

TEST_CASE("reading a missing or broken file is an error naming it", "[image_io]") {
    std::string error;
    const std::string missing = scratchFile("missing.png");
    CHECK_FALSE(readImage(missing, error));
    CHECK_THAT(error, Catch::Contains(missing));

    const std::string broken = scratchFile("broken.png");
    std::ofstream(broken) << "this is not a PNG";
    error.clear();
    CHECK_FALSE(readImage(broken, error));
    CHECK_THAT(error, Catch::Contains(broken));
    INFO(error);
    CHECK(error.size() > broken.size() + 16); // says why, too

    error.clear();
    CHECK_FALSE(describeImage(missing, error));
    CHECK_THAT(error, Catch::Contains(missing));
}

TEST_CASE("an image of more pixels than allowed is refused from its header", "[image_io]") {
    std::string error;
    const std::string path = scratchFile("four_by_four.png");
    REQUIRE(writeImage(path, codeGradient(4, 4), {}, error));
    CHECK(readImage(path, error, nullptr, 16));
    CHECK_FALSE(readImage(path, error, nullptr, 15));
    CHECK(error == "cannot read \"" + path + "\": it is 4 x 4 pixels, more than the 15 allowed; raise "
                   "the limit with --max-image-pixels");

    // A header claiming 30000 x 30000 with no pixel data after it: 13.5 GB once decoded.
    const std::string claim = scratchFile("claims_30000.ppm");
    std::ofstream(claim) << "P6\n30000 30000\n255\n";
    CHECK_FALSE(readImage(claim, error, nullptr, 100'000'000));
    CHECK_THAT(error, Catch::Contains("it is 30000 x 30000 pixels"));
}

TEST_CASE("pixels of more than four channels count as many pixels of four against the limit",
          "[image_io]") {
    // 16 x 16 pixels of 1000 channels (RGB and 997 extra): the values of 64,000 pixels of four.
    constexpr int kSide = 16, kChannels = 1000;
    std::vector<std::uint8_t> values(std::size_t(kSide) * kSide * kChannels);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = std::uint8_t(i % kChannels + i / kChannels);
    const std::string path = scratchFile("thousand_channels.tif");
    std::ofstream(path, std::ios::binary)
        << deflatedTiff(kSide, kSide, kChannels, false, 8, values);
    std::string error;
    CHECK_FALSE(readImage(path, error, nullptr, 63'999));
    CHECK(error ==
          "cannot read \"" + path +
              "\": it is 16 x 16 pixels of 1000 channels, more values "
              "than the 63999 pixels allowed hold at four channels each; raise the limit with "
              "--max-image-pixels");
    error.clear();
    CHECK_FALSE(describeImage(path, error, 63'999));
    CHECK_THAT(error, Catch::Contains("of 1000 channels"));
    // At the limit the image is read: its first three channels (and an alpha, if it has one).
    const std::optional<ImageBuffer> image = readImage(path, error, nullptr, 64'000);
    INFO(error);
    REQUIRE(image);
    std::size_t wrong = 0;
    for (std::size_t pixel = 0; pixel < std::size_t(kSide) * kSide; ++pixel)
        for (std::size_t c = 0; c < 3; ++c)
            wrong += image->pixels[pixel * image->channels + c] !=
                     float(values[pixel * kChannels + c]) / 255.0f;
    CHECK(wrong == 0);
    // Up to four channels only the pixels count.
    const std::string rgba = scratchFile("rgba_16.png");
    REQUIRE(writeImage(rgba,
                       ImageBuffer{kSide, kSide, 4, std::vector<float>(kSide * kSide * 4, 0.5f)},
                       {}, error));
    CHECK(readImage(rgba, error, nullptr, kSide * kSide));
}

TEST_CASE("concurrent writes and reads of different files", "[image_io]") {
    constexpr int kThreads = 6;
    std::vector<int> failures(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            const ImageBuffer image = codeGradient(32 + t, 16);
            for (int n = 0; n < 5; ++n) {
                const std::string path =
                    scratchFile("thread" + std::to_string(t) + (n % 2 ? ".png" : ".tif"));
                std::string error;
                bool ok = writeImage(path, image, {}, error);
                const std::optional<ImageBuffer> back = ok ? readImage(path, error) : std::nullopt;
                ok = back && back->pixels == image.pixels;
                if (!ok) ++failures[t];
            }
        });
    for (std::thread& thread : threads) thread.join();
    for (int t = 0; t < kThreads; ++t) CHECK(failures[t] == 0);
    // Nothing but finished images in the directory: no temporary survived the races.
    for (const std::string& name : scratchListing()) CHECK(name.find(".tmp") == std::string::npos);
}

TEST_CASE("the PNG compression level trades size for time, never pixels", "[image_io]") {
    // A smooth two-axis ramp with a little pattern: compressible, but not trivially.
    ImageBuffer image{96, 64, 3, {}};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            image.pixels.push_back(float(x) / float(image.width));
            image.pixels.push_back(float(y) / float(image.height));
            image.pixels.push_back(float((x * 7 + y * 3) % 11) / 10.0f);
        }
    std::string error;
    std::vector<std::uintmax_t> sizes;
    std::optional<ImageBuffer> first;
    for (int level : {0, 2, 9}) {
        const std::string path = scratchFile("level" + std::to_string(level) + ".png");
        WriteOptions options;
        options.pngCompression = level;
        REQUIRE(writeImage(path, image, options, error));
        sizes.push_back(fs::file_size(path));
        ImageBuffer back = readOrFail(path);
        if (!first) first = back;
        CHECK(back.pixels == first->pixels);
    }
    CHECK(sizes[0] > sizes[1]);
    CHECK(sizes[1] > sizes[2]);

    WriteOptions tooHigh;
    tooHigh.pngCompression = 10;
    CHECK_FALSE(writeImage(scratchFile("level10.png"), image, tooHigh, error));
    CHECK_THAT(error, Catch::Contains("compression level must be 0 to 9"));
}

TEST_CASE("an image streamed in bands of rows equals the image written whole", "[image_io]") {
    const ImageBuffer image = codeGradient(37, 23);
    for (const char* name : {"bands.png", "bands.exr", "bands.tif"}) {
        const std::string path = scratchFile(name);
        std::string error;
        auto stream = ImageStream::open(path, image.width, image.height, 3, {}, error);
        INFO(error);
        REQUIRE(stream);
        // Uneven bands, like a render's tile rows with a short last one.
        const std::size_t rowValues = std::size_t(image.width) * 3;
        for (int y = 0; y < image.height; y += 5) {
            const int end = std::min(y + 5, image.height);
            std::span<const float> rows(image.pixels.data() + y * rowValues, (end - y) * rowValues);
            REQUIRE(stream->writeRows(y, end, rows, error));
        }
        // Nothing under the final name until the stream is finished.
        CHECK_FALSE(fs::exists(path));
        REQUIRE(stream->finish(error));
        CHECK(readOrFail(path).pixels == image.pixels);
    }
}

TEST_CASE("a stream refuses rows out of order and an early finish, and leaves no file",
          "[image_io]") {
    const ImageBuffer image = codeGradient(8, 6);
    const std::size_t rowValues = 8 * 3;
    const std::string path = scratchFile("unfinished.png");
    const auto before = scratchListing();
    std::string error;
    {
        auto stream = ImageStream::open(path, 8, 6, 3, {}, error);
        REQUIRE(stream);
        std::span<const float> two(image.pixels.data(), 2 * rowValues);
        CHECK_FALSE(stream->writeRows(2, 4, two, error)); // row 0 comes first
        CHECK_THAT(error, Catch::Contains("do not follow row 0"));
        REQUIRE(stream->writeRows(0, 2, two, error));
        CHECK_FALSE(stream->writeRows(2, 3, two, error)); // wrong value count
        CHECK_FALSE(stream->finish(error));
        CHECK_THAT(error, Catch::Contains("only 2 of 6 rows"));
    }
    // Destroyed unfinished: the temporary file is gone and no image appeared.
    CHECK_FALSE(fs::exists(path));
    CHECK(scratchListing() == before);

    CHECK_FALSE(ImageStream::open(scratchFile("no_dir/x.png"), 8, 6, 3, {}, error));
    CHECK_THAT(error, Catch::Contains("does not exist"));
    CHECK_FALSE(ImageStream::open(scratchFile("x.png"), 0, 6, 3, {}, error));
    CHECK_THAT(error, Catch::Contains("empty"));
}

TEST_CASE("files OpenImageIO's readers would abort on or reserve gigabytes for are refused", "[image_io]") {
    auto writeBytes = [](const std::string& path, const std::string& bytes) {
        std::ofstream(path, std::ios::binary) << bytes;
    };
    std::string error;

    // OpenEXR: a header attribute announcing 1.8 GB in a file of a few bytes (the reader
    // reserves it before reading).
    std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    exr += std::string("comments\0string\0", 16) + std::string("\x00\x00\x00\x70", 4) + "text";
    const std::string hugeAttribute = scratchFile("huge_attribute.exr");
    writeBytes(hugeAttribute, exr);
    CHECK_FALSE(readImage(hugeAttribute, error));
    CHECK_THAT(error, Catch::Contains("damaged OpenEXR file: a header attribute is longer than the file"));
    error.clear();
    CHECK_FALSE(describeImage(hugeAttribute, error));
    CHECK_THAT(error, Catch::Contains("damaged OpenEXR file"));
    // A name longer than OpenEXR reads (31 bytes without the long-names flag): OpenEXR would
    // go on reading the rest of it as the type name and the size. With the flag, 255.
    std::string longName("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    longName += std::string(32, 'n') + std::string("\0string\0", 8) + std::string("\x04\x00\x00\x00", 4) + "text";
    const std::string tooLong = scratchFile("long_attribute_name.exr");
    writeBytes(tooLong, longName);
    error.clear();
    CHECK_FALSE(readImage(tooLong, error));
    CHECK_THAT(error, Catch::Contains("damaged OpenEXR file: an attribute's name is too long"));
    longName[5] = '\x04'; // long names: the same attribute is read to its end
    writeBytes(tooLong, longName);
    error.clear();
    CHECK_FALSE(readImage(tooLong, error));
    CHECK_THAT(error, !Catch::Contains("name is too long"));
    // A valid OpenEXR file passes the check, named for its format or not.
    const ImageBuffer image{2, 2, 3, std::vector<float>(12, 0.5f)};
    const std::string valid = scratchFile("valid.exr");
    writeOrFail(valid, image, {});
    const std::string unnamed = scratchFile("valid_exr_without_extension");
    fs::copy_file(valid, unnamed, fs::copy_options::overwrite_existing);
    CHECK(readOrFail(unnamed).pixels == image.pixels);

    // RLA (no magic number): a header the RLA reader accepts, with color channel type 3, on
    // which it fails an assertion. The RLA reader is never asked: refused by name, and not
    // among the readers tried on a file its extension's reader does not open.
    std::string rla(744, '\0');
    rla[19] = 3;                                     // ColorChannelType
    rla[21] = 3;                                     // NumOfColorChannels
    rla[26] = '\xff', rla[27] = '\xfe';              // Revision
    rla[659] = 8;                                    // NumOfChannelBits
    for (const char* name : {"channel_type_3.rla", "channel_type_3.png", "channel_type_3"}) {
        const std::string path = scratchFile(name);
        writeBytes(path, rla);
        error.clear();
        CHECK_FALSE(readImage(path, error));
        CHECK_FALSE(error.empty());
    }
    CHECK_THAT(error, Catch::Contains("not an image file OpenImageIO reads"));
    error.clear();
    CHECK_FALSE(readImage(scratchFile("channel_type_3.rla"), error));
    CHECK_THAT(error, Catch::Contains("RLA images are not supported"));

    // SGI: its reader read through a null pointer, or took 4 GB, on damaged files.
    const std::string sgi = scratchFile("one_pixel.sgi");
    writeBytes(sgi, std::string("\x01\xda\x00\x01\x00\x01\x00\x01\x00\x01\x00\x01", 12) + std::string(500, '\0'));
    error.clear();
    CHECK_FALSE(readImage(sgi, error));
    CHECK_THAT(error, Catch::Contains(
                          "SGI images are not supported (convert the file to PNG, TIFF or OpenEXR)"));

    // HEIF: its reader copied rows of the width the header announces out of a smaller
    // decoded image (tests/fuzz/regressions/image/heif-grid-smaller-than-header). Refused by
    // each extension OpenImageIO gives it, whatever the contents.
    for (const char* name : {"picture.heic", "picture.HEIF", "picture.avif"}) {
        const std::string path = scratchFile(name);
        writeBytes(path, std::string("\0\0\0\x1c" "ftypheic", 12) + std::string(500, '\0'));
        error.clear();
        CHECK_FALSE(readImage(path, error));
        CHECK_THAT(error, Catch::Contains("HEIF images are not supported"));
    }

    // FITS: its reader reserved 8 GB for a damaged header. Never used either, even on a
    // valid header.
    std::string fits = "SIMPLE  =                    T";
    fits.resize(80, ' ');
    for (const char* card : {"BITPIX  =                    8", "NAXIS   =                    2",
                             "NAXIS1  =                    1", "NAXIS2  =                    1", "END"}) {
        std::string line = card;
        line.resize(80, ' ');
        fits += line;
    }
    fits.resize(2880, ' ');
    fits += std::string(2880, '\x80');
    for (const char* name : {"one_pixel.fits", "one_pixel"}) {
        const std::string path = scratchFile(name);
        writeBytes(path, fits);
        error.clear();
        CHECK_FALSE(readImage(path, error));
        CHECK_THAT(error, Catch::Contains(name == std::string("one_pixel") ? "not an image file OpenImageIO reads"
                                                                          : "FITS images are not supported"));
    }
}

TEST_CASE("an image whose rows begin near the end of int's range is refused, not read for seconds",
          "[image_io]") {
    // The fuzzing finding: a 2 KB little-endian DPX of 1 x 1664 pixels whose row origin
    // (YOffset, bytes 1412..1415) is 0x7fc00000, where OpenImageIO's count of rows overflows.
    // The same file with other origins around the limit (2^30 for the last row's end).
    std::ifstream in(CRT_FUZZ_REGRESSIONS_DIR "/image/dpx-row-origin-near-int-max.dpx", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() > 1416);
    auto withRowOrigin = [&](uint32_t origin) {
        std::string patched = bytes;
        for (int i = 0; i < 4; ++i) patched[1412 + i] = char(origin >> 8 * i);
        const std::string path = scratchFile("origin_" + std::to_string(origin) + ".dpx");
        std::ofstream(path, std::ios::binary) << patched;
        return path;
    };
    constexpr uint32_t kHeight = 1664, kLimit = uint32_t{1} << 30;
    std::string error;
    for (uint32_t origin : {uint32_t{0x7fc00000}, kLimit - kHeight + 1}) {
        error.clear();
        CHECK_FALSE(readImage(withRowOrigin(origin), error));
        CHECK_THAT(error, Catch::Contains("damaged image file: its pixels lie too far from the origin"));
    }
    // Rows that begin nearer are read, the same pixels wherever they begin.
    const ImageBuffer image = readOrFail(withRowOrigin(0));
    CHECK(image.height == int(kHeight));
    CHECK(readOrFail(withRowOrigin(kLimit - kHeight)).pixels == image.pixels);
}

TEST_CASE("a min-is-white TIFF with alpha in deflated strips reads inverted, within its buffer",
          "[image_io]") {
    // Strips of 1 MB: OpenImageIO's faulty path (readPixels in the module) wrote a whole strip
    // past the end of the image, far enough to reach memory that is not there.
    constexpr int kWidth = 1024, kHeight = 1024, kRowsPerStrip = 512;
    std::vector<std::uint8_t> values;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            values.insert(values.end(), {std::uint8_t(x * 7 + y * 3), std::uint8_t(x)});
    const std::string path = scratchFile("min_is_white.tif");
    std::ofstream(path, std::ios::binary)
        << deflatedTiff(kWidth, kHeight, 2, true, kRowsPerStrip, values);
    const ImageBuffer image = readOrFail(path);
    REQUIRE(image.width == kWidth);
    REQUIRE(image.height == kHeight);
    REQUIRE(image.channels == 4); // grey and alpha: the grey made RGB, the alpha as stored
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < std::size_t(kWidth) * kHeight; ++i) {
        const float white = float(255 - values[i * 2]) / 255.0f;
        const float* p = &image.pixels[i * 4];
        wrong += p[0] != white || p[1] != white || p[2] != white ||
                 std::abs(p[3] - float(values[i * 2 + 1]) / 255.0f) > 1e-6f;
    }
    CHECK(wrong == 0);
}

TEST_CASE("a TIFF strip of more rows than the image holds the image, whatever it claims",
          "[image_io]") {
    // Nearly 2^31 rows or more a strip: OpenImageIO 2.4 took forever over the whole image
    // or aborted (readPixels in the module).
    constexpr int kSide = 16;
    std::vector<std::uint8_t> values(std::size_t(kSide) * kSide * 3);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::uint8_t(i * 5);
    for (std::uint32_t rowsPerStrip : {32u, 2'147'000'000u, 2'147'483'648u, 4'000'000'000u}) {
        INFO(rowsPerStrip);
        const std::string path = scratchFile("strip_" + std::to_string(rowsPerStrip) + ".tif");
        std::ofstream(path, std::ios::binary)
            << deflatedTiff(kSide, kSide, 3, false, rowsPerStrip, values);
        const ImageBuffer image = readOrFail(path);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < values.size(); ++i)
            wrong += image.pixels[i] != float(values[i]) / 255.0f;
        CHECK(wrong == 0);
    }
}

TEST_CASE("CMYK TIFFs of values OpenImageIO 2.4 unpacks past its buffer are refused",
          "[image_io]") {
    // 16 x 16 pixels of 4-bit CMYK, uncompressed, in one strip.
    const std::string path = CRT_FUZZ_REGRESSIONS_DIR "/image/tiff-cmyk-4-bit.tif";
    std::string error;
    CHECK_FALSE(readImage(path, error));
    CHECK(error ==
          "cannot read \"" + path +
              "\": CMYK TIFF images of 4-bit values are not supported (convert the file to "
              "8 or 16 bits)");
    // Its header is read, as the size limit needs it.
    const std::optional<ImageInfo> info = describeImage(path, error);
    REQUIRE(info);
    CHECK(info->width == 16);
}

TEST_CASE("sizes an image's header claims are limited before OpenImageIO opens it", "[image_io]") {
    auto writeBytes = [](const std::string& path, const std::string& bytes) {
        std::ofstream(path, std::ios::binary) << bytes;
    };
    std::string error;
    // A GIF whose logical screen is 50,000 x 50,000: OpenImageIO's reader reserves the canvas
    // when it opens the file, so the limit applies to the screen before any frame is read.
    std::string gif("GIF89a\x50\xc3\x50\xc3\x00\x00\x00", 13);
    gif += ";";
    const std::string hugeScreen = scratchFile("huge_screen.gif");
    writeBytes(hugeScreen, gif);
    CHECK_FALSE(readImage(hugeScreen, error, nullptr, 100'000'000));
    CHECK_THAT(error, Catch::Contains("it is 50000 x 50000 pixels, more than the 100000000 allowed"));
    error.clear();
    CHECK_FALSE(describeImage(hugeScreen, error, 100'000'000));
    CHECK_THAT(error, Catch::Contains("50000 x 50000 pixels"));

    // A BMP whose header claims 50,000 x 50,000 (rows from the top: a negative height), run-length
    // coded: OpenImageIO's reader decodes such an image whole while it opens the file.
    auto little32 = [](int32_t value) {
        std::string bytes(4, '\0');
        for (int i = 0; i < 4; ++i) bytes[size_t(i)] = char(uint32_t(value) >> (8 * i) & 0xff);
        return bytes;
    };
    std::string bmp = "BM" + little32(70) + little32(0) + little32(54);
    bmp += little32(40) + little32(50000) + little32(-50000) + std::string("\x01\x00\x08\x00", 4) + little32(1);
    bmp.resize(70, '\0');
    const std::string hugeBmp = scratchFile("huge.bmp");
    writeBytes(hugeBmp, bmp);
    error.clear();
    CHECK_FALSE(readImage(hugeBmp, error, nullptr, 100'000'000));
    CHECK_THAT(error, Catch::Contains("it is 50000 x 50000 pixels, more than the 100000000 allowed"));
    // RLE8 codes in a 24-bit image: OpenImageIO's reader read past the rows it decoded them into.
    std::string mixed = "BM" + little32(70) + little32(0) + little32(54);
    mixed += little32(40) + little32(4) + little32(4) + std::string("\x01\x00\x18\x00", 4) + little32(1);
    mixed.resize(70, '\0');
    const std::string mixedBmp = scratchFile("rle8_24_bits.bmp");
    writeBytes(mixedBmp, mixed);
    error.clear();
    CHECK_FALSE(readImage(mixedBmp, error));
    CHECK_THAT(error, Catch::Contains("damaged BMP file: run-length coding of 8-bit pixels in an image of 24-bit pixels"));

    // OpenEXR reserves a buffer for the lines it decompresses at once when it opens a file,
    // as wide as the data window and, with ZIP (crtc's default), 16 lines high: a 4 x 4 image
    // counts as 4 x 16.
    const ImageBuffer image{4, 4, 3, std::vector<float>(48, 0.25f)};
    const std::string valid = scratchFile("window.exr");
    writeOrFail(valid, image, {});
    CHECK(readImage(valid, error, nullptr, 64));
    CHECK_FALSE(readImage(valid, error, nullptr, 63));
    CHECK_THAT(error, Catch::Contains("it is 4 x 16 pixels"));
    // Its data window made 2^24 pixels wide.
    std::ifstream in(valid, std::ios::binary);
    std::string exr((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t window = exr.find(std::string("dataWindow\0box2i\0", 17));
    REQUIRE(window != std::string::npos);
    const size_t xMax = window + 17 + 4 + 8;
    exr.replace(xMax, 4, std::string("\xff\xff\xff\x00", 4));
    const std::string wide = scratchFile("wide_window.exr");
    writeBytes(wide, exr);
    error.clear();
    CHECK_FALSE(readImage(wide, error, nullptr, 100'000'000));
    CHECK_THAT(error, Catch::Contains("it is 16777216 x"));
    CHECK_THAT(error, Catch::Contains("--max-image-pixels"));

    // A typed attribute whose declared size is not its type's: OpenEXR would read the next
    // attribute from elsewhere than the declared size says.
    exr.replace(window + 17, 4, std::string("\x14\x00\x00\x00", 4));
    const std::string shifted = scratchFile("shifted_window.exr");
    writeBytes(shifted, exr);
    error.clear();
    CHECK_FALSE(readImage(shifted, error));
    CHECK_THAT(error, Catch::Contains("damaged OpenEXR file: attribute 'dataWindow' of type box2i declares 20 bytes, not 16"));
}
