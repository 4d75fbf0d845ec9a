// The built-in PNG writer, checked by a small decoder here (chunks, CRCs, inflate, the Sub
// filter), without OpenImageIO. image_io_test.cpp reads the same files through OpenImageIO.
#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/image_io.hpp"

#include <catch2/catch.hpp>
#include <zlib.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace crt::tracer::image_io;
namespace fs = std::filesystem;

namespace {

struct Chunk {
    std::string type;
    std::vector<std::uint8_t> data;
};

struct DecodedPng {
    std::vector<Chunk> chunks;
    int width = 0, height = 0, colourType = -1;
    std::vector<std::uint8_t> codes; ///< unfiltered, row-major
};

std::uint32_t bigEndian32(const std::uint8_t* at) {
    return std::uint32_t(at[0]) << 24 | std::uint32_t(at[1]) << 16 | std::uint32_t(at[2]) << 8 |
           at[3];
}

// The CRC-32 of ISO 3309 computed bit by bit, independent of zlib's table-driven one.
std::uint32_t referenceCrc(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

// Decodes what the writer produces (8 bits, no interlace; filters None and Sub only).
DecodedPng decode(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(in),
                                         std::istreambuf_iterator<char>()};
    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    REQUIRE(file.size() >= 8);
    REQUIRE(std::equal(signature, signature + 8, file.begin()));
    DecodedPng png;
    std::vector<std::uint8_t> deflated;
    for (std::size_t at = 8; at < file.size();) {
        REQUIRE(at + 12 <= file.size());
        const std::uint32_t size = bigEndian32(&file[at]);
        REQUIRE(at + 12 + size <= file.size());
        Chunk chunk{std::string(file.begin() + long(at) + 4, file.begin() + long(at) + 8),
                    std::vector<std::uint8_t>(file.begin() + long(at) + 8,
                                              file.begin() + long(at) + 8 + size)};
        INFO("chunk " << chunk.type);
        CHECK(bigEndian32(&file[at + 8 + size]) == referenceCrc(&file[at + 4], 4 + size));
        if (chunk.type == "IDAT")
            deflated.insert(deflated.end(), chunk.data.begin(), chunk.data.end());
        png.chunks.push_back(std::move(chunk));
        at += 12 + size;
    }
    REQUIRE(png.chunks.size() >= 3);
    REQUIRE(png.chunks.front().type == "IHDR");
    REQUIRE(png.chunks.back().type == "IEND");
    const std::vector<std::uint8_t>& header = png.chunks.front().data;
    REQUIRE(header.size() == 13);
    png.width = int(bigEndian32(&header[0]));
    png.height = int(bigEndian32(&header[4]));
    png.colourType = header[9];
    REQUIRE(header[8] == 8);
    REQUIRE(header[12] == 0);
    const std::size_t channels = png.colourType == 0 ? 1 : png.colourType == 2 ? 3 : 4;
    const std::size_t rowBytes = std::size_t(png.width) * channels;

    std::vector<std::uint8_t> raw(std::size_t(png.height) * (rowBytes + 1));
    uLongf rawSize = uLongf(raw.size());
    REQUIRE(uncompress(raw.data(), &rawSize, deflated.data(), uLong(deflated.size())) == Z_OK);
    REQUIRE(rawSize == raw.size());
    for (int y = 0; y < png.height; ++y) {
        const std::uint8_t* row = &raw[std::size_t(y) * (rowBytes + 1)];
        REQUIRE(row[0] <= 1); // None or Sub
        const std::size_t start = png.codes.size();
        for (std::size_t i = 0; i < rowBytes; ++i) {
            const std::uint8_t left =
                row[0] == 1 && i >= channels ? png.codes[start + i - channels] : 0;
            png.codes.push_back(std::uint8_t(row[1 + i] + left));
        }
    }
    return png;
}

std::vector<std::string> chunkTypes(const DecodedPng& png) {
    std::vector<std::string> types;
    for (const Chunk& chunk : png.chunks)
        if (types.empty() || chunk.type != types.back() || chunk.type != "IDAT")
            types.push_back(chunk.type);
    return types;
}

bool openImageIoMapped() {
    std::ifstream maps("/proc/self/maps");
    const std::string text{std::istreambuf_iterator<char>(maps), std::istreambuf_iterator<char>()};
    return text.find("libOpenImageIO") != std::string::npos;
}

struct ScratchPath {
    fs::path path;
    explicit ScratchPath(const std::string& name)
        : path(fs::temp_directory_path() / (std::to_string(getpid()) + "." + name)) {}
    ~ScratchPath() {
        std::error_code ec;
        fs::remove(path, ec);
    }
};

// Noise-like values: deflate cannot shrink them much, so a large image spans many chunks.
ImageBuffer pattern(int width, int height, int channels) {
    ImageBuffer image{width, height, channels, {}};
    std::uint32_t state = 12345;
    for (int i = 0; i < width * height * channels; ++i) {
        state = state * 1664525u + 1013904223u;
        image.pixels.push_back(float(state >> 24) / 255.0f);
    }
    return image;
}

} // namespace

TEST_CASE("a PNG is written without loading OpenImageIO", "[image_io][png]") {
    const ScratchPath file("no_module.png");
    std::string error;
    REQUIRE(writeImage(file.path.string(), pattern(7, 5, 3), {}, error));
    CHECK(fs::exists(file.path));
    CHECK_FALSE(openImageIoMapped());
    CHECK_FALSE(writingNeedsModule("a.png"));
    CHECK_FALSE(writingNeedsModule("a.PNG"));
    CHECK(writingNeedsModule("a.tif"));
    CHECK(writingNeedsModule("a.gif"));
    CHECK_FALSE(writingNeedsModule("a.bmp")); // unsupported: an error without the module
}

TEST_CASE("the built-in PNG writer stores grey, RGB and RGBA codes exactly", "[image_io][png]") {
    for (int channels : {1, 3, 4}) {
        INFO(channels << " channels");
        const ScratchPath file("codes" + std::to_string(channels) + ".png");
        const ImageBuffer image = pattern(29, 17, channels);
        std::string error;
        REQUIRE(writeImage(file.path.string(), image, {}, error));
        const DecodedPng png = decode(file.path.string());
        CHECK(png.width == 29);
        CHECK(png.height == 17);
        CHECK(png.colourType == (channels == 1 ? 0 : channels == 3 ? 2 : 6));
        CHECK(png.codes == quantise8(image.pixels, 1.0, false));
        CHECK(chunkTypes(png) == std::vector<std::string>{"IHDR", "IDAT", "IEND"});
    }
}

TEST_CASE("an sRGB PNG says so, and alpha is stored without the transfer function",
          "[image_io][png]") {
    const ScratchPath file("srgb.png");
    const ImageBuffer image{2, 1, 4, {0.5f, 0.25f, 0.0f, 0.5f, 1.0f, 0.1f, 0.9f, 0.25f}};
    WriteOptions options;
    options.srgb = true;
    std::string error;
    REQUIRE(writeImage(file.path.string(), image, options, error));
    const DecodedPng png = decode(file.path.string());
    CHECK(chunkTypes(png) == std::vector<std::string>{"IHDR", "sRGB", "gAMA", "IDAT", "IEND"});
    CHECK(png.codes == std::vector<std::uint8_t>{encodeSrgb8(0.5f), encodeSrgb8(0.25f), 0, 128, 255,
                                                 encodeSrgb8(0.1f), encodeSrgb8(0.9f), 64});
}

TEST_CASE("a large PNG streamed in bands spans many data chunks and decodes exactly",
          "[image_io][png]") {
    const ImageBuffer image = pattern(301, 211, 3); // about 190 kB of codes
    for (int level : {0, 2, 9}) {
        INFO("level " << level);
        const ScratchPath file("large" + std::to_string(level) + ".png");
        WriteOptions options;
        options.pngCompression = level;
        std::string error;
        auto stream =
            ImageStream::open(file.path.string(), image.width, image.height, 3, options, error);
        REQUIRE(stream);
        const std::size_t rowValues = std::size_t(image.width) * 3;
        for (int y = 0; y < image.height; y += 16) {
            const int end = std::min(y + 16, image.height);
            REQUIRE(stream->writeRows(
                y, end,
                std::span<const float>(image.pixels.data() + y * rowValues, (end - y) * rowValues),
                error));
        }
        REQUIRE(stream->finish(error));
        const DecodedPng png = decode(file.path.string());
        CHECK(png.codes == quantise8(image.pixels, 1.0, false));
        std::size_t dataChunks = 0;
        for (const Chunk& chunk : png.chunks) dataChunks += chunk.type == "IDAT";
        CHECK(dataChunks >= 2);
    }
}
