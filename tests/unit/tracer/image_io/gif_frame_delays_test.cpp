// GIF frame delays: the hundredths that keep an animation's rate, and reading and setting
// them in a file.
#include "tracer/image_io/gif_frame_delays.hpp"

#include "../scratch_folder.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numeric>

using namespace crt::tracer::image_io;

TEST_CASE("GIF delays keep the frame rate over the whole animation", "[image_io][gif]") {
    for (double fps : {1.0, 7.0, 12.0, 15.0, 23.976, 24.0, 25.0, 29.97, 30.0, 60.0, 100.0}) {
        INFO(fps << " fps");
        const std::vector<std::uint16_t> delays = gifFrameDelays(300, fps);
        REQUIRE(delays.size() == 300);
        long elapsed = 0;
        for (size_t i = 0; i < delays.size(); ++i) {
            CHECK(delays[i] >= std::floor(100.0 / fps));
            CHECK(delays[i] <= std::ceil(100.0 / fps));
            elapsed += delays[i];
            // Every frame ends within half a hundredth of where the rate puts it.
            CHECK(std::abs(elapsed - (i + 1) * 100.0 / fps) <= 0.5 + 1e-9);
        }
    }
    CHECK(gifFrameDelays(3, 15.0) == std::vector<std::uint16_t>{7, 6, 7});
    CHECK(gifFrameDelays(2, 1000.0) == std::vector<std::uint16_t>{1, 1}); // at least 1
}

TEST_CASE("Delays are read from and set in a GIF's graphic control extensions", "[image_io][gif]") {
    // Two 1 x 1 frames with a two-colour global table, each behind a graphic control extension.
    const std::vector<unsigned char> gif = {
        'G',  'I',  'F', '8', '9',  'a', 1, 0, 1, 0, 0x80, 0, 0, // screen, a 2-colour table
        0,    0,    0,   255, 255,  255,                         // the table
        0x21, 0xF9, 4,   0,   10,   0,   0, 0,                   // delay 10
        0x2C, 0,    0,   0,   0,    1,   0, 1, 0, 0, 2,    2, 0x4C, 0x01, 0, // the first frame
        0x21, 0xFE, 3,   'a', 'b',  'c', 0,                                  // a comment
        0x21, 0xF9, 4,   0,   0x2C, 1,   0, 0,                               // delay 300 (0x12C)
        0x2C, 0,    0,   0,   0,    1,   0, 1, 0, 0, 2,    2, 0x4C, 0x01, 0, // the second frame
        0x3B};
    const std::string path = crt::tracer::test::scratchFile("delays.gif");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(gif.data()), static_cast<std::streamsize>(gif.size()));
    std::string error;
    std::optional<std::vector<std::uint16_t>> delays = readGifDelays(path, error);
    INFO(error);
    REQUIRE(delays);
    CHECK(*delays == std::vector<std::uint16_t>{10, 300});

    REQUIRE(writeGifDelays(path, {7, 6}, error));
    delays = readGifDelays(path, error);
    REQUIRE(delays);
    CHECK(*delays == std::vector<std::uint16_t>{7, 6});
    CHECK_FALSE(writeGifDelays(path, {7, 6, 7}, error)); // three delays for two frames

    // Damaged files are refused, not read past their end.
    for (size_t cut : {size_t{5}, size_t{20}, size_t{30}, gif.size() - 1}) {
        INFO("cut at " << cut);
        std::ofstream(path, std::ios::binary | std::ios::trunc)
            .write(reinterpret_cast<const char*>(gif.data()), static_cast<std::streamsize>(cut));
        CHECK_FALSE(readGifDelays(path, error));
        CHECK_FALSE(writeGifDelays(path, {1, 1}, error));
    }
}
