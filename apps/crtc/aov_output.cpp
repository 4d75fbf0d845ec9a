#include "aov_output.hpp"

#include "tracer/image_io/image_io.hpp"

#include <fmt/format.h>

#include <filesystem>

namespace crt::crtc {

AovOutput::AovOutput(std::string target, int width, int height, int colorChannels, tracer::AovSet aovs)
    : target_(std::move(target)), colorChannels_(colorChannels), aovs_(aovs),
      buffer_(width, height, aovs.channels()) {}

std::string AovOutput::path(const std::string& target, tracer::Aov aov) {
    const std::string extension = fmt::format(".{}.exr", tracer::kAovNames[static_cast<size_t>(aov)]);
    return std::filesystem::path(target).replace_extension(extension).string();
}

tracer::TileResult AovOutput::take(const tracer::TileResult& tile, std::vector<float>& color) {
    const size_t pixels = static_cast<size_t>(tile.tile.width()) * tile.tile.height();
    const size_t aovChannels = static_cast<size_t>(buffer_.channels);
    color.resize(pixels * colorChannels_);
    std::vector<float> aovs(pixels * aovChannels);
    for (size_t i = 0; i < pixels; ++i) {
        const float* in = tile.pixels.data() + i * static_cast<size_t>(tile.channels);
        std::copy_n(in, colorChannels_, color.data() + i * colorChannels_);
        std::copy_n(in + colorChannels_, aovChannels, aovs.data() + i * aovChannels);
    }
    buffer_.place(tracer::TileResult{tile.tile, tile.index, buffer_.channels, aovs});
    return tracer::TileResult{tile.tile, tile.index, colorChannels_, color};
}

bool AovOutput::write(std::string& error) const {
    int first = 0; // the channel of the next AOV in the buffer
    for (size_t a = 0; a < tracer::kAovNames.size(); ++a) {
        const auto aov = static_cast<tracer::Aov>(a);
        if (!aovs_.has(aov)) continue;
        tracer::image_io::ImageBuffer image{buffer_.width, buffer_.height, 3, {}};
        image.pixels.reserve(static_cast<size_t>(buffer_.width) * buffer_.height * 3);
        for (size_t i = 0; i < buffer_.pixels.size(); i += static_cast<size_t>(buffer_.channels))
            image.pixels.insert(image.pixels.end(), buffer_.pixels.begin() + static_cast<long>(i) + first,
                                buffer_.pixels.begin() + static_cast<long>(i) + first + 3);
        if (!tracer::image_io::writeImage(path(target_, aov), image, {}, error)) return false;
        first += 3;
    }
    return true;
}

} // namespace crt::crtc
