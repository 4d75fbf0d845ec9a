// A finished tile as a worker sends it to rank 0: its index in the job, then its floats.
#pragma once

#include "tracer/renderer.hpp"

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

} // namespace crt::crtc::distributed
