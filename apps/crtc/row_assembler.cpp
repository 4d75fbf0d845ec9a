// Bands of finished rows from tiles.
#include "row_assembler.hpp"

#include <algorithm>

namespace crt::crtc {

RowAssembler::RowAssembler(int width, int height, int channels, Emit emit)
    : channels_(static_cast<size_t>(channels)), rowValues_(static_cast<size_t>(width) * channels_),
      emit_(std::move(emit)), pixelsLeft_(static_cast<size_t>(height), width) {}

/// Grows the ring so that it holds rows nextRow_ to y. Its size stays a multiple of the
/// renderer's tile size, so that where a band of whole tile rows wraps around, it is split
/// between two tile rows.
void RowAssembler::makeRoomFor(int y) {
    const int needed = y - nextRow_ + 1;
    if (needed <= ringRows_) return;
    int rows = std::max(2 * ringRows_, needed);
    rows = (rows + tracer::kTileSize - 1) / tracer::kTileSize * tracer::kTileSize;
    std::vector<float> grown(static_cast<size_t>(rows) * rowValues_);
    for (int row = nextRow_; row < nextRow_ + ringRows_; ++row)
        std::copy_n(rowAt(row), rowValues_,
                    grown.data() + static_cast<size_t>(row % rows) * rowValues_);
    ring_ = std::move(grown);
    ringRows_ = rows;
}

void RowAssembler::add(const tracer::TileResult& result) {
    const tracer::Tile& tile = result.tile;
    makeRoomFor(tile.y1 - 1);
    const size_t tileRowValues = static_cast<size_t>(tile.width()) * channels_;
    for (int y = tile.y0; y < tile.y1; ++y) {
        std::copy_n(result.pixels.data() + static_cast<size_t>(y - tile.y0) * tileRowValues,
                    tileRowValues, rowAt(y) + static_cast<size_t>(tile.x0) * channels_);
        pixelsLeft_[static_cast<size_t>(y)] -= tile.width();
    }
    emitFinished();
}

void RowAssembler::emitFinished() {
    int end = nextRow_;
    while (end < static_cast<int>(pixelsLeft_.size()) && pixelsLeft_[static_cast<size_t>(end)] == 0)
        ++end;
    while (nextRow_ < end) { // in one piece, or two where the rows wrap around the ring
        const int run = std::min(end - nextRow_, ringRows_ - nextRow_ % ringRows_);
        emit_(nextRow_, nextRow_ + run,
              std::span<const float>(rowAt(nextRow_), static_cast<size_t>(run) * rowValues_));
        nextRow_ += run;
    }
}

} // namespace crt::crtc
