// crtc's row assembler: tiles in any order in, bands of finished rows out, in order, once each.
#include "row_assembler.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

using crt::crtc::RowAssembler;
using namespace crt::tracer;

namespace {

/// A test image whose every value tells where it is.
float valueAt(int x, int y, int c) { return static_cast<float>((y * 1000 + x) * 4 + c); }

TileResult tileOf(const Tile& tile, int index, int channels, std::vector<float>& storage) {
    storage.clear();
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x)
            for (int c = 0; c < channels; ++c) storage.push_back(valueAt(x, y, c));
    return {tile, index, channels, storage};
}

} // namespace

TEST_CASE("Finished rows are emitted once each, in order, with their values", "[crtc]") {
    const int width = 53, height = 37; // a last tile column of 5 pixels, a last tile row of 5
    const int channels = GENERATE(3, 4); // RGB, and RGB with alpha
    INFO(channels << " channels");
    std::vector<Tile> tiles = imageTiles(width, height);
    REQUIRE(tiles.size() == 12);
    std::mt19937 shuffle(5);
    for (int round = 0; round < 4; ++round) {
        INFO("round " << round);
        if (round > 0) std::shuffle(tiles.begin(), tiles.end(), shuffle);
        std::vector<float> emitted;
        int nextRow = 0, calls = 0;
        bool ordered = true;
        RowAssembler rows(width, height, channels, [&](int yBegin, int yEnd, std::span<const float> values) {
            ordered = ordered && yBegin == nextRow && yEnd > yBegin &&
                      values.size() == static_cast<size_t>(yEnd - yBegin) * width * channels;
            nextRow = yEnd;
            ++calls;
            emitted.insert(emitted.end(), values.begin(), values.end());
        });
        std::vector<float> storage;
        for (size_t i = 0; i < tiles.size(); ++i)
            rows.add(tileOf(tiles[i], static_cast<int>(i), channels, storage));
        CHECK(ordered);
        CHECK(nextRow == height);
        CHECK(calls >= 1);
        CHECK(calls <= 3); // at most once per tile row: 16, 16 and 5 rows
        if (round == 0) CHECK(calls == 3); // in order, each tile row completes on its own
        std::vector<float> expected;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < channels; ++c) expected.push_back(valueAt(x, y, c));
        CHECK(emitted == expected);
    }
}

TEST_CASE("No row is emitted before every pixel of it is finished", "[crtc]") {
    int calls = 0;
    RowAssembler rows(32, 16, 3, [&](int, int, std::span<const float>) { ++calls; });
    std::vector<float> storage;
    rows.add(tileOf({16, 0, 32, 16}, 0, 3, storage));
    CHECK(calls == 0); // the left half of the rows is missing
    rows.add(tileOf({0, 8, 16, 16}, 1, 3, storage));
    CHECK(calls == 0); // rows 8 to 15 are whole, but rows 0 to 7 above them are not
    rows.add(tileOf({0, 0, 16, 8}, 2, 3, storage));
    CHECK(calls == 1);
}

TEST_CASE("Rows held while the rows above them are traced come out whole and in order", "[crtc]") {
    // One tile column, its tile rows finished in this order: rows below a missing one wait,
    // and the held rows span more than the buffer held before.
    const int width = 16, height = 16 * 8;
    const int order[] = {0, 2, 1, 5, 4, 3, 7, 6};
    std::vector<float> emitted;
    int nextRow = 0, calls = 0;
    bool ordered = true;
    RowAssembler rows(width, height, 3, [&](int yBegin, int yEnd, std::span<const float> values) {
        ordered = ordered && yBegin == nextRow && yEnd > yBegin &&
                  values.size() == static_cast<size_t>(yEnd - yBegin) * width * 3;
        nextRow = yEnd;
        ++calls;
        emitted.insert(emitted.end(), values.begin(), values.end());
    });
    std::vector<float> storage;
    for (int tileRow : order)
        rows.add(tileOf({0, tileRow * 16, width, tileRow * 16 + 16}, tileRow, 3, storage));
    CHECK(ordered);
    CHECK(nextRow == height);
    CHECK(calls <= 8); // never more than once per tile row
    std::vector<float> expected;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) expected.push_back(valueAt(x, y, c));
    CHECK(emitted == expected);
}
