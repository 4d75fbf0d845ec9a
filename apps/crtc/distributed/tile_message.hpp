// Finished tiles as a worker sends them to rank 0: each its index in the job, then its floats;
// several in one batch. And which tiles each rank traces in a time-limited render.
#pragma once

#include "tracer/renderer.hpp"

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace crt::crtc::distributed {

inline std::vector<char> encodeTile(const tracer::TileResult& result) {
    std::vector<char> message(sizeof(int) + result.pixels.size_bytes());
    std::memcpy(message.data(), &result.index, sizeof(int));
    std::memcpy(message.data() + sizeof(int), result.pixels.data(), result.pixels.size_bytes());
    return message;
}

/// The tile of `tiles` a message carries with `channels` floats a pixel, or false for a message
/// that is not one of them.
inline bool decodeTile(const std::vector<char>& message, const std::vector<tracer::Tile>& tiles,
                       int channels, std::vector<float>& pixels, int& index) {
    if (message.size() < sizeof(int)) return false;
    std::memcpy(&index, message.data(), sizeof(int));
    if (index < 0 || index >= static_cast<int>(tiles.size())) return false;
    const tracer::Tile& tile = tiles[static_cast<size_t>(index)];
    const size_t values = static_cast<size_t>(tile.width()) * tile.height() * channels;
    if (message.size() != sizeof(int) + values * sizeof(float)) return false;
    pixels.resize(values);
    std::memcpy(pixels.data(), message.data() + sizeof(int), values * sizeof(float));
    return true;
}

/// Tiles of one frame sent together: the frame's number, then each tile (encodeTile) after
/// its size. One message for the tiles a worker finished since it last sent, rather than one
/// each: a message waits for the receiver to take the one before it, and a worker whose tiles
/// take less than that wait would spend its main thread sending instead of asking for work.
class TileBatch {
  public:
    explicit TileBatch(int32_t frame) { append(&frame, sizeof frame); }
    void add(const std::vector<char>& tile) {
        const uint32_t size = static_cast<uint32_t>(tile.size());
        append(&size, sizeof size);
        append(tile.data(), tile.size());
    }
    bool empty() const { return bytes_.size() == sizeof(int32_t); }
    const std::vector<char>& bytes() const { return bytes_; }

    /// Calls `take` with each tile of a batch's bytes; false for bytes that are not a batch.
    template <class Take> static bool split(const std::vector<char>& bytes, Take&& take) {
        size_t at = sizeof(int32_t);
        while (at < bytes.size()) {
            uint32_t size = 0;
            if (bytes.size() - at < sizeof size) return false;
            std::memcpy(&size, bytes.data() + at, sizeof size);
            at += sizeof size;
            if (bytes.size() - at < size) return false;
            take(std::vector<char>(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                                   bytes.begin() + static_cast<std::ptrdiff_t>(at + size)));
            at += size;
        }
        return at == bytes.size();
    }

  private:
    void append(const void* data, size_t size) {
        const char* begin = static_cast<const char*>(data);
        bytes_.insert(bytes_.end(), begin, begin + size);
    }
    std::vector<char> bytes_;
};

/// The ints a message of tile indices (or of one count) carries.
inline std::vector<int> intsOf(const std::vector<char>& message) {
    std::vector<int> values(message.size() / sizeof(int));
    if (!values.empty()) std::memcpy(values.data(), message.data(), values.size() * sizeof(int));
    return values;
}

/// Tiles as the ints broadcast to the ranks: x0, y0, x1, y1 of each.
inline std::vector<int> tileCorners(const std::vector<tracer::Tile>& tiles) {
    std::vector<int> corners;
    corners.reserve(tiles.size() * 4);
    for (const tracer::Tile& t : tiles) corners.insert(corners.end(), {t.x0, t.y0, t.x1, t.y1});
    return corners;
}

inline std::vector<tracer::Tile> tilesOfCorners(const std::vector<int>& corners) {
    std::vector<tracer::Tile> tiles;
    for (size_t i = 0; i + 3 < corners.size(); i += 4)
        tiles.push_back({corners[i], corners[i + 1], corners[i + 2], corners[i + 3]});
    return tiles;
}

/// The tiles (indices in the job) rank `rank` of `ranks` traces in a time-limited render,
/// where each rank refines its own tiles pass after pass until the common deadline rather than
/// asking for tiles: every ranks-th tile, so that each rank's share samples the whole image
/// and costly regions are spread over all of them.
inline std::vector<int> timeLimitedShare(int tileCount, int rank, int ranks) {
    std::vector<int> share;
    for (int t = rank; t < tileCount; t += ranks) share.push_back(t);
    return share;
}

} // namespace crt::crtc::distributed
