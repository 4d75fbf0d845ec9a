// The 8-bit output transfer functions and the sRGB decode, exactly as spec §6 "Output" states them.
#include "tracer/image_io/encoding.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace crt::tracer::image_io;

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
} // namespace

TEST_CASE("gamma encoding gives the spec's exact codes", "[image_io][encoding]") {
    CHECK(encodeGamma8(0.0f, 1.0) == 0);
    CHECK(encodeGamma8(1.0f, 1.0) == 255);
    CHECK(encodeGamma8(0.5f, 1.0) == 128); // 127.5 + ½ rounds up
    CHECK(encodeGamma8(0.5f, 2.2) == 186); // 255 · 0.5^(1/2.2) = 186.08
    CHECK(encodeGamma8(0.25f, 2.0) == 128);
    CHECK(encodeGamma8(1.0f, 2.2) == 255);
    CHECK(encodeGamma8(0.0f, 2.2) == 0);
}

TEST_CASE("gamma 1 stores k/255 as k for every code", "[image_io][encoding]") {
    for (int k = 0; k <= 255; ++k) {
        INFO("k = " << k);
        CHECK(encodeGamma8(float(k) / 255.0f, 1.0) == k);
    }
}

TEST_CASE("out-of-range and NaN values are clamped", "[image_io][encoding]") {
    for (const double gamma : {1.0, 2.2, 0.45}) {
        INFO("gamma = " << gamma);
        CHECK(encodeGamma8(-0.5f, gamma) == 0);
        CHECK(encodeGamma8(-kInf, gamma) == 0);
        CHECK(encodeGamma8(kNaN, gamma) == 0);
        CHECK(encodeGamma8(1.5f, gamma) == 255);
        CHECK(encodeGamma8(kInf, gamma) == 255);
        CHECK(encodeGamma8(std::nextafter(1.0f, 2.0f), gamma) == 255);
    }
    CHECK(encodeSrgb8(-0.5f) == 0);
    CHECK(encodeSrgb8(kNaN) == 0);
    CHECK(encodeSrgb8(-kInf) == 0);
    CHECK(encodeSrgb8(7.0f) == 255);
    CHECK(encodeSrgb8(kInf) == 255);
    CHECK(linearToSrgb(kNaN) == 0.0f);
    CHECK(linearToSrgb(3.0f) == 1.0f);
}

TEST_CASE("sRGB encoding follows IEC 61966-2-1", "[image_io][encoding]") {
    CHECK(encodeSrgb8(0.0f) == 0);
    CHECK(encodeSrgb8(1.0f) == 255);
    CHECK(encodeSrgb8(0.5f) == 188);  // 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354
    CHECK(encodeSrgb8(0.18f) == 118); // middle grey
    CHECK(encodeSrgb8(0.001f) == 3);  // linear segment: 255 · 12.92 · 0.001 = 3.29
    CHECK(linearToSrgb(0.0031308f) == Approx(0.04045).epsilon(1e-4)); // the segments meet
}

TEST_CASE("sRGB decoding inverts the encoding", "[image_io][encoding]") {
    CHECK(srgbToLinear(0.0f) == 0.0f);
    CHECK(srgbToLinear(1.0f) == 1.0f);
    CHECK(srgbToLinear(0.04045f) == Approx(0.04045 / 12.92));
    CHECK(srgbToLinear(188.0f / 255.0f) == Approx(0.5).epsilon(0.01));
    CHECK(srgbToLinear(-1.0f) == 0.0f);
    CHECK(srgbToLinear(kNaN) == 0.0f);
    // Every 8-bit code survives decode then encode: reading and writing an sRGB image is lossless.
    for (int k = 0; k <= 255; ++k) {
        INFO("k = " << k);
        CHECK(encodeSrgb8(srgbToLinear(float(k) / 255.0f)) == k);
    }
    for (float x = 0.0f; x <= 1.0f; x += 0.01f)
        CHECK(srgbToLinear(linearToSrgb(x)) == Approx(x).margin(1e-6));
}

TEST_CASE("encodings are monotone", "[image_io][encoding]") {
    int lastGamma = 0, lastSrgb = 0;
    for (int i = 0; i <= 100000; ++i) {
        const float c = float(i) / 100000.0f;
        const int gamma = encodeGamma8(c, 2.2), srgb = encodeSrgb8(c);
        REQUIRE(gamma >= lastGamma);
        REQUIRE(srgb >= lastSrgb);
        lastGamma = gamma;
        lastSrgb = srgb;
    }
    CHECK(lastGamma == 255);
    CHECK(lastSrgb == 255);
}

TEST_CASE("quantise8 applies one transfer function to every value", "[image_io][encoding]") {
    const std::vector<float> values{0.0f, 0.5f, 1.0f, -1.0f, kNaN, 2.0f, 0.25f};
    const std::vector<std::uint8_t> gamma = quantise8(values, 2.2, false);
    const std::vector<std::uint8_t> srgb = quantise8(values, 2.2, true); // sRGB wins over gamma
    REQUIRE(gamma.size() == values.size());
    REQUIRE(srgb.size() == values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        CHECK(gamma[i] == encodeGamma8(values[i], 2.2));
        CHECK(srgb[i] == encodeSrgb8(values[i]));
    }
    CHECK(quantise8({}, 1.0, false).empty());
}

TEST_CASE("quantise8 matches the exact formula at every code boundary", "[image_io][encoding]") {
    // quantise8 uses a table of boundaries, not a pow per value: probe every boundary's
    // neighbourhood, a fine sweep and random bit patterns against the per-value functions.
    for (const double gamma : {1.0, 2.2, 1.8, 0.45, 3.0, 1.0 / 2.2}) {
        for (const bool srgb : {false, true}) {
            std::vector<float> values;
            for (int k = 1; k < 256; ++k) {
                const double edge = (k - 0.5) / 255.0;
                const double linear =
                    srgb ? (edge <= 0.04045 ? edge / 12.92 : std::pow((edge + 0.055) / 1.055, 2.4))
                         : std::pow(edge, gamma);
                float c = std::nextafter(float(linear), 0.0f);
                for (int i = 0; i < 4; ++i) c = std::nextafter(c, 0.0f);
                for (int i = 0; i < 9; ++i, c = std::nextafter(c, 2.0f)) values.push_back(c);
            }
            for (int i = 0; i <= 200000; ++i) values.push_back(float(i) / 200000.0f);
            std::mt19937 random(7);
            std::uniform_int_distribution<std::uint32_t> bits(0, 0x3f800000u);
            for (int i = 0; i < 200000; ++i) {
                const std::uint32_t b = bits(random);
                float c;
                std::memcpy(&c, &b, sizeof c);
                values.push_back(c);
            }
            values.insert(values.end(), {-1.0f, kNaN, kInf, -kInf, 1.0f, 2.0f, 0.0f, -0.0f});

            const std::vector<std::uint8_t> codes = quantise8(values, gamma, srgb);
            REQUIRE(codes.size() == values.size());
            std::size_t mismatches = 0;
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::uint8_t exact =
                    srgb ? encodeSrgb8(values[i]) : encodeGamma8(values[i], gamma);
                if (codes[i] != exact) ++mismatches;
            }
            INFO("gamma " << gamma << " srgb " << srgb);
            CHECK(mismatches == 0);
        }
    }
}
