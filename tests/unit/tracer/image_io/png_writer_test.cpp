// PNG output, read back with libpng: exact codes, the colour chunks, compression levels,
// streaming, failed writes, and never a load of OpenImageIO.
#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/image_io.hpp"

#include "../scratch_folder.hpp"

#include <catch2/catch.hpp>
#include <png.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

using namespace crt::tracer::image_io;
namespace fs = std::filesystem;

namespace {

using namespace crt::tracer::test;

// --- reading back with libpng

// The header and the stored codes of a PNG, as libpng reads them without transformations.
struct DecodedPng {
    png_uint_32 width = 0, height = 0;
    int bitDepth = 0, colourType = -1, interlace = -1;
    std::vector<std::uint8_t> codes; ///< row-major, as stored
    std::string problem;             ///< libpng's error or first warning; empty if none
};

// libpng's errors and warnings: kept in a plain buffer, then (errors) a jump back to a setjmp.
struct ReadState {
    char message[256] = {};
};

void onReadError(png_structp png, png_const_charp message) {
    auto* state = static_cast<ReadState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "error: %s", message);
    png_longjmp(png, 1);
}

void onReadWarning(png_structp png, png_const_charp message) {
    auto* state = static_cast<ReadState*>(png_get_error_ptr(png));
    if (state->message[0] == '\0')
        std::snprintf(state->message, sizeof state->message, "warning: %s", message);
}

// The steps that call into libpng hold only plain data, so its longjmp skips no destructor.
bool readInfo(png_structp png, png_infop info, std::FILE* file, DecodedPng* out) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_set_user_limits(png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    // Every chunk's CRC must hold, the colour chunks' too (by default only a warning).
    png_set_crc_action(png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
    png_read_info(png, info);
    png_get_IHDR(png, info, &out->width, &out->height, &out->bitDepth, &out->colourType,
                 &out->interlace, nullptr, nullptr);
    return true;
}

bool readRows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info); // through IEND, checking the remaining chunks
    return true;
}

DecodedPng decode(const std::string& path) {
    DecodedPng result;
    ReadState state;
    struct Close {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    const std::unique_ptr<std::FILE, Close> file(std::fopen(path.c_str(), "rb"));
    REQUIRE(file);
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, onReadError, onReadWarning);
    REQUIRE(png);
    png_infop info = png_create_info_struct(png);
    struct Destroy {
        png_structp& png;
        png_infop& info;
        ~Destroy() { png_destroy_read_struct(&png, &info, nullptr); }
    } destroy{png, info};
    REQUIRE(info);
    if (readInfo(png, info, file.get(), &result) && result.bitDepth == 8) {
        const std::size_t rowBytes = png_get_rowbytes(png, info);
        result.codes.resize(rowBytes * result.height);
        std::vector<png_bytep> rows(result.height);
        for (png_uint_32 y = 0; y < result.height; ++y) rows[y] = &result.codes[y * rowBytes];
        readRows(png, info, rows.data());
    }
    result.problem = state.message;
    return result;
}

struct Chunk {
    std::string type;
    std::vector<std::uint8_t> data;
};

// The chunks of a file in order (libpng checks their CRCs in decode).
std::vector<Chunk> chunksOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    std::vector<Chunk> chunks;
    for (std::size_t at = 8; at + 12 <= bytes.size();) {
        const std::size_t size = std::size_t(bytes[at]) << 24 | std::size_t(bytes[at + 1]) << 16 |
                                 std::size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        REQUIRE(at + 12 + size <= bytes.size());
        chunks.push_back({std::string(bytes.begin() + long(at) + 4, bytes.begin() + long(at) + 8),
                          std::vector<std::uint8_t>(bytes.begin() + long(at) + 8,
                                                    bytes.begin() + long(at + 8 + size))});
        at += 12 + size;
    }
    return chunks;
}

// The chunk types, with a run of IDAT chunks shown once.
std::vector<std::string> chunkTypes(const std::string& path) {
    std::vector<std::string> types;
    for (const Chunk& chunk : chunksOf(path))
        if (types.empty() || chunk.type != "IDAT" || types.back() != "IDAT")
            types.push_back(chunk.type);
    return types;
}

const Chunk* findChunk(const std::vector<Chunk>& chunks, const std::string& type) {
    for (const Chunk& chunk : chunks)
        if (chunk.type == type) return &chunk;
    return nullptr;
}

// --- images

// Noise-like values in [0, 1]: deflate cannot shrink them much.
ImageBuffer noise(int width, int height, int channels) {
    ImageBuffer image{width, height, channels, {}};
    std::uint32_t state = 12345;
    for (long i = 0; i < long(width) * height * channels; ++i) {
        state = state * 1664525u + 1013904223u;
        image.pixels.push_back(float(state >> 8) / float(1 << 24));
    }
    return image;
}

// Smooth ramps with a little pattern: compressible, but not trivially.
ImageBuffer ramps(int width, int height) {
    ImageBuffer image{width, height, 3, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.pixels.insert(image.pixels.end(),
                                {float(x) / float(width), float(y) / float(height),
                                 float((x * 7 + y * 3) % 11) / 10.0f});
    return image;
}

// The codes the spec asks for, value by value through the scalar encoders: colour through the
// transfer function, a fourth channel (alpha) linear.
std::vector<std::uint8_t> expectedCodes(const ImageBuffer& image, const WriteOptions& options) {
    std::vector<std::uint8_t> codes;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float v = image.pixels[i];
        const bool alpha = image.channels == 4 && i % 4 == 3;
        codes.push_back(alpha          ? encodeGamma8(v, 1.0)
                        : options.srgb ? encodeSrgb8(v)
                                       : encodeGamma8(v, options.gamma));
    }
    return codes;
}

void writeOrFail(const std::string& path, const ImageBuffer& image,
                 const WriteOptions& options = {}) {
    std::string error;
    const bool ok = writeImage(path, image, options, error);
    INFO(error);
    REQUIRE(ok);
}

// Sets a resource's soft limit for the scope (SIGXFSZ ignored, so that exceeding the file
// size limit is an EFBIG error rather than the end of the process).
class SoftLimit {
  public:
    SoftLimit(int resource, rlim_t value) : resource_(resource) {
        REQUIRE(getrlimit(resource, &saved_) == 0);
        rlimit changed = saved_;
        changed.rlim_cur = value;
        REQUIRE(setrlimit(resource, &changed) == 0);
        savedHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    }
    ~SoftLimit() {
        setrlimit(resource_, &saved_);
        std::signal(SIGXFSZ, savedHandler_);
    }
    SoftLimit(const SoftLimit&) = delete;
    SoftLimit& operator=(const SoftLimit&) = delete;

  private:
    int resource_;
    rlimit saved_{};
    void (*savedHandler_)(int) = nullptr;
};

} // namespace

TEST_CASE("a PNG is written without loading OpenImageIO", "[image_io][png]") {
    // The module is not beside this test and CRT_IMAGE_IO_MODULE is unset: a write that
    // needed it would fail, besides mapping the library.
    writeOrFail(scratchFile("no_module.png"), noise(7, 5, 3));
    std::string error;
    auto stream = ImageStream::open(scratchFile("no_module_stream.png"), 4, 2, 1, {}, error);
    INFO(error);
    REQUIRE(stream);
    REQUIRE(stream->writeRows(0, 2, std::vector<float>(8, 0.5f), error));
    REQUIRE(stream->finish(error));
    CHECK(decode(scratchFile("no_module_stream.png")).codes == std::vector<std::uint8_t>(8, 128));
    CHECK_FALSE(openImageIoMapped());
}

TEST_CASE("grey, RGB and RGBA are stored as the spec's 8-bit codes", "[image_io][png]") {
    const WriteOptions linear{}, gamma22{2.2, false}, srgb{1.0, true};
    for (int channels : {1, 3, 4}) {
        for (const WriteOptions& options : {linear, gamma22, srgb}) {
            INFO(channels << " channels, gamma " << options.gamma << ", srgb " << options.srgb);
            const std::string path = scratchFile("codes.png");
            ImageBuffer image = noise(29, 17, channels);
            // NaN, values outside [0, 1] and its ends, which the encoding clamps.
            const float special[] = {std::numeric_limits<float>::quiet_NaN(), -0.5f, 3.0f, 1.0f,
                                     0.0f};
            std::copy(std::begin(special), std::end(special), image.pixels.begin());
            writeOrFail(path, image, options);
            const DecodedPng png = decode(path);
            INFO(png.problem);
            CHECK(png.problem.empty());
            CHECK(png.width == 29);
            CHECK(png.height == 17);
            CHECK(png.bitDepth == 8);
            CHECK(png.interlace == PNG_INTERLACE_NONE);
            CHECK(png.colourType == (channels == 1   ? PNG_COLOR_TYPE_GRAY
                                     : channels == 3 ? PNG_COLOR_TYPE_RGB
                                                     : PNG_COLOR_TYPE_RGB_ALPHA));
            CHECK(png.codes == expectedCodes(image, options));
        }
    }
}

TEST_CASE("alpha is stored straight and linear, whatever the colour encoding", "[image_io][png]") {
    const std::string path = scratchFile("alpha.png");
    const ImageBuffer image{2, 1, 4, {0.5f, 0.25f, 0.0f, 0.5f, 1.0f, 0.1f, 0.9f, 0.25f}};
    writeOrFail(path, image, {1.0, true});
    // Colour through sRGB (0.5 → 188), alpha not (0.5 → 128, 0.25 → 64), and the colour of a
    // half-transparent pixel not divided by its alpha.
    CHECK(decode(path).codes == std::vector<std::uint8_t>{188, 137, 0, 128, 255, 89, 243, 64});
}

TEST_CASE("an sRGB PNG carries the sRGB and gAMA chunks, others no colour chunk",
          "[image_io][png]") {
    const std::string path = scratchFile("chunks.png");
    for (const WriteOptions& options : {WriteOptions{1.0, false}, WriteOptions{2.2, false}}) {
        INFO("gamma " << options.gamma);
        writeOrFail(path, ramps(16, 8), options);
        CHECK(decode(path).problem.empty());
        CHECK(chunkTypes(path) == std::vector<std::string>{"IHDR", "IDAT", "IEND"});
    }
    writeOrFail(path, ramps(16, 8), {1.0, true});
    CHECK(decode(path).problem.empty()); // a gAMA contradicting the sRGB chunk draws a warning
    std::vector<std::string> types = chunkTypes(path);
    REQUIRE(types.size() == 5);
    CHECK(types.front() == "IHDR");
    std::sort(types.begin() + 1, types.begin() + 3); // their order is free
    CHECK(std::vector<std::string>(types.begin() + 1, types.end()) ==
          std::vector<std::string>{"gAMA", "sRGB", "IDAT", "IEND"});
    const std::vector<Chunk> chunks = chunksOf(path);
    REQUIRE(findChunk(chunks, "sRGB"));
    CHECK(findChunk(chunks, "sRGB")->data == std::vector<std::uint8_t>{0}); // perceptual
    REQUIRE(findChunk(chunks, "gAMA"));
    // 45455: 1/2.2 in units of 1e-5, the value the PNG specification pairs with sRGB.
    CHECK(findChunk(chunks, "gAMA")->data == std::vector<std::uint8_t>{0, 0, 0xb1, 0x8f});
}

TEST_CASE("every compression level gives a valid file of the same codes", "[image_io][png]") {
    const ImageBuffer image = ramps(96, 64);
    const std::vector<std::uint8_t> expected = expectedCodes(image, {});
    std::vector<std::uintmax_t> sizes;
    for (int level = 0; level <= 9; ++level) {
        INFO("level " << level);
        const std::string path = scratchFile("level" + std::to_string(level) + ".png");
        WriteOptions options;
        options.pngCompression = level;
        writeOrFail(path, image, options);
        const DecodedPng png = decode(path);
        INFO(png.problem);
        CHECK(png.problem.empty());
        CHECK(png.codes == expected);
        sizes.push_back(fs::file_size(path));
    }
    // Level 0 stores the rows uncompressed (a filter byte each, and framing); the level is
    // passed on, so higher ones shrink the file.
    CHECK(sizes[0] > 64 * (1 + 96 * 3));
    CHECK(sizes[0] > sizes[2]);
    CHECK(sizes[2] > sizes[9]);
}

TEST_CASE("a streamed PNG reaches the file row by row and equals one written whole",
          "[image_io][png]") {
    const ImageBuffer image = noise(600, 400, 3);
    const std::string whole = scratchFile("whole.png"), streamed = scratchFile("streamed.png");
    writeOrFail(whole, image);
    std::string error;
    auto stream = ImageStream::open(streamed, image.width, image.height, 3, {}, error);
    INFO(error);
    REQUIRE(stream);
    const std::size_t rowValues = std::size_t(image.width) * 3;
    std::uintmax_t halfway = 0;
    for (int y = 0; y < image.height; y += 23) { // uneven bands, a short last one
        const int end = std::min(y + 23, image.height);
        REQUIRE(stream->writeRows(
            y, end,
            std::span<const float>(image.pixels.data() + y * rowValues, (end - y) * rowValues),
            error));
        if (end >= image.height / 2 && halfway == 0) {
            for (const std::string& name : scratchListing())
                if (name.ends_with(".tmp")) halfway = fs::file_size(scratch() / name);
        }
    }
    // Noise hardly compresses: half the rows are over 300 kB, most of which must be on disk
    // already rather than held until finish.
    CHECK(halfway > 200'000);
    CHECK_FALSE(fs::exists(streamed));
    REQUIRE(stream->finish(error));
    CHECK(decode(streamed).codes == expectedCodes(image, {}));
    std::ifstream a(whole, std::ios::binary), b(streamed, std::ios::binary);
    CHECK(std::string(std::istreambuf_iterator<char>(a), {}) ==
          std::string(std::istreambuf_iterator<char>(b), {}));
}

TEST_CASE("an image wider than libpng's default reading limit is written", "[image_io][png]") {
    const std::string path = scratchFile("wide.png");
    ImageBuffer image{1'000'001, 1, 1, std::vector<float>(1'000'001, 0.0f)};
    image.pixels.back() = 1.0f;
    writeOrFail(path, image);
    const DecodedPng png = decode(path);
    INFO(png.problem);
    CHECK(png.width == 1'000'001);
    REQUIRE(png.codes.size() == 1'000'001);
    CHECK(png.codes.front() == 0);
    CHECK(png.codes.back() == 255);
}

TEST_CASE("a PNG write that fails on the disk reports why and leaves nothing", "[image_io][png]") {
    // A file size limit plays a full disk.
    const std::string path = scratchFile("full.png");
    const auto before = scratchListing();
    const auto checkError = [&](const std::string& error) {
        CHECK_THAT(error, Catch::StartsWith("cannot write \"" + path + "\"") &&
                              Catch::Contains(std::strerror(EFBIG)));
        CHECK(error.find(".tmp") == std::string::npos); // the temporary is not named
    };
    SECTION("hit while rows are written: the stream fails then, and stays failed") {
        const ImageBuffer image = noise(300, 200, 3);
        const std::size_t rowValues = std::size_t(image.width) * 3;
        const auto band = [&](int y) {
            return std::span<const float>(image.pixels.data() + y * rowValues, 10 * rowValues);
        };
        std::string error;
        int failedAt = -1;
        {
            // Nothing else writes a file under the limit (Catch's output might).
            std::optional<SoftLimit> limit(std::in_place, RLIMIT_FSIZE, 64);
            auto stream = ImageStream::open(path, image.width, image.height, 3, {}, error);
            for (int y = 0; stream && y < image.height && failedAt < 0; y += 10)
                if (!stream->writeRows(y, y + 10, band(y), error)) failedAt = y;
            limit.reset();
            REQUIRE(stream);
            REQUIRE(failedAt >= 0);
            checkError(error);
            // With room again, the broken stream must not carry on as if nothing happened.
            std::string again;
            CHECK_FALSE(stream->writeRows(failedAt, failedAt + 10, band(failedAt), again));
            CHECK_THAT(again, Catch::Contains(std::strerror(EFBIG)));
            for (int y = failedAt; y < image.height; y += 10)
                stream->writeRows(y, y + 10, band(y), again);
            CHECK_FALSE(stream->finish(again));
        } // the stream, destroyed unfinished, removes its temporary
        CHECK_FALSE(fs::exists(path));
    }
    SECTION("hit only when the file is closed (a small image, still in stdio's buffer)") {
        const ImageBuffer image = noise(8, 8, 3);
        std::string error;
        bool written = true;
        {
            const SoftLimit limit(RLIMIT_FSIZE, 64);
            written = writeImage(path, image, {}, error);
        }
        CHECK_FALSE(written);
        checkError(error);
    }
    CHECK(scratchListing() == before);
}

TEST_CASE("a PNG whose file cannot be created is an error, and leaves nothing", "[image_io][png]") {
    const std::string path = scratchFile("no_descriptor.png");
    const auto before = scratchListing();
    const ImageBuffer image = noise(4, 4, 3);
    std::string error;
    bool written = true;
    {
        // No descriptor left: the lowest free one is at the limit. Nothing else happens under
        // it (the sanitizers' checks, too, need a descriptor).
        const int lowest = dup(0);
        REQUIRE(lowest >= 0);
        close(lowest);
        const SoftLimit limit(RLIMIT_NOFILE, rlim_t(lowest));
        written = writeImage(path, image, {}, error);
    }
    CHECK_FALSE(written);
    CHECK_THAT(error, Catch::Contains(path) && Catch::Contains(std::strerror(EMFILE)));
    CHECK(scratchListing() == before);
}

TEST_CASE("a PNG into a missing directory is an error, and creates nothing", "[image_io][png]") {
    const std::string path = scratchFile("missing/out.png");
    const auto before = scratchListing();
    std::string error;
    CHECK_FALSE(writeImage(path, noise(4, 4, 3), {}, error));
    CHECK_THAT(error, Catch::Contains(path) && Catch::Contains("does not exist"));
    CHECK_FALSE(ImageStream::open(path, 4, 4, 3, {}, error));
    CHECK_THAT(error, Catch::Contains("does not exist"));
    CHECK(scratchListing() == before);
}
