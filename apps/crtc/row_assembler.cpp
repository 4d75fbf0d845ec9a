// Bands of finished rows from tiles.
#include "row_assembler.hpp"

#include <algorithm>

namespace crt::crtc {

RowAssembler::RowAssembler(int width, int height, int channels, Emit emit)
    : width_(width), channels_(channels), emit_(std::move(emit)),
      pixelsLeft_(static_cast<size_t>(height), width) {}

void RowAssembler::add(const tracer::TileResult& result) {
    const tracer::Tile& tile = result.tile;
    const size_t channels = static_cast<size_t>(channels_);
    const size_t tileRowValues = static_cast<size_t>(tile.width()) * channels;
    for (int y = tile.y0; y < tile.y1; ++y) {
        std::vector<float>& row = pending_[y];
        if (row.empty() && !spareRows_.empty()) {
            row = std::move(spareRows_.back());
            spareRows_.pop_back();
        }
        if (row.empty()) row.resize(static_cast<size_t>(width_) * channels);
        std::copy_n(result.pixels.data() + static_cast<size_t>(y - tile.y0) * tileRowValues,
                    tileRowValues, row.data() + static_cast<size_t>(tile.x0) * channels);
        pixelsLeft_[static_cast<size_t>(y)] -= tile.width();
    }
    emitFinished();
}

void RowAssembler::emitFinished() {
    const int begin = nextRow_;
    band_.clear();
    while (nextRow_ < static_cast<int>(pixelsLeft_.size()) &&
           pixelsLeft_[static_cast<size_t>(nextRow_)] == 0) {
        auto row = pending_.find(nextRow_);
        band_.insert(band_.end(), row->second.begin(), row->second.end());
        spareRows_.push_back(std::move(row->second));
        pending_.erase(row);
        ++nextRow_;
    }
    if (nextRow_ > begin) emit_(begin, nextRow_, band_);
}

} // namespace crt::crtc
