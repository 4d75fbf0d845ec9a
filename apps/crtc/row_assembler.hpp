// Turns finished tiles, which come in any order, into bands of finished rows, in order from
// the top: what an image file written while the render goes on needs.
#pragma once

#include "tracer/renderer.hpp"

#include <functional>
#include <span>
#include <vector>

namespace crt::crtc {

class RowAssembler {
public:
    /// Receives rows [yBegin, yEnd), the tiles' floats row-major, each row once, in order from
    /// the top.
    using Emit = std::function<void(int yBegin, int yEnd, std::span<const float> pixels)>;

    /// Tiles of `channels` floats a pixel.
    RowAssembler(int width, int height, int channels, Emit emit);

    /// Takes a finished tile (tiles must not overlap); emits the rows it completes, with those
    /// below them that were waiting. Holds the rows from the first not emitted to the lowest
    /// begun, in a buffer kept at the most such rows there were.
    void add(const tracer::TileResult& tile);

private:
    void makeRoomFor(int y);
    float* rowAt(int y) { return ring_.data() + static_cast<size_t>(y % ringRows_) * rowValues_; }
    void emitFinished();

    size_t channels_;  ///< floats a pixel
    size_t rowValues_; ///< floats a row
    Emit emit_;
    std::vector<int> pixelsLeft_; ///< per row of the image
    int nextRow_ = 0;             ///< the first row not emitted
    /// The rows from nextRow_ on, row y in slot y % ringRows_: kept from tile to tile, since
    /// fresh memory costs a page fault every 4 KB, and emitted from where they lie.
    std::vector<float> ring_;
    int ringRows_ = 0;
};

} // namespace crt::crtc
