// Turns finished tiles, which come in any order, into bands of finished rows, in order from
// the top: what an image file written while the render goes on needs.
#pragma once

#include "tracer/renderer.hpp"

#include <functional>
#include <map>
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
    /// below them that were waiting. Holds only the rows not yet emitted.
    void add(const tracer::TileResult& tile);

private:
    void emitFinished();

    int width_;
    int channels_;
    Emit emit_;
    std::vector<int> pixelsLeft_;               ///< per row of the image
    std::map<int, std::vector<float>> pending_; ///< rows begun but not emitted
    int nextRow_ = 0;                           ///< the first row not emitted
    // Kept for the next rows and bands: fresh memory costs a page fault every 4 KB, which
    // for a simple scene is a good part of the time its rows take to trace.
    std::vector<std::vector<float>> spareRows_;
    std::vector<float> band_;
};

} // namespace crt::crtc
