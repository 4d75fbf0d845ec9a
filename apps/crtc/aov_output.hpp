// The AOV images of a frame (--aov): taken from its tiles as they are finished, each written
// as an EXR file beside the image once the frame is done.
#pragma once

#include "tracer/renderer.hpp"

#include <string>
#include <vector>

namespace crt::crtc {

class AovOutput {
public:
    /// For the image `target` of `width` × `height` pixels whose tiles carry `colorChannels`
    /// floats a pixel and then the AOVs of `aovs`.
    AovOutput(std::string target, int width, int height, int colorChannels, tracer::AovSet aovs);

    /// Where the AOV `aov` of the image `target` goes: "out.png" → "out.albedo.exr".
    static std::string path(const std::string& target, tracer::Aov aov);

    /// Keeps the AOVs of `tile` (placed in the image); returns its colour alone, in `color`.
    tracer::TileResult take(const tracer::TileResult& tile, std::vector<float>& color);
    /// Writes every AOV image; false, with the reason, when one cannot be written.
    bool write(std::string& error) const;

private:
    std::string target_;
    int colorChannels_;
    tracer::AovSet aovs_;
    tracer::PixelBuffer buffer_; ///< the AOVs' channels, in the order of tracer::Aov
};

} // namespace crt::crtc
