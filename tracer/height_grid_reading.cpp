// The heights of a scene's HeightField: read from its image, or sampled from its Function.
#include "tracer/height_grid_reading.hpp"

#include "tracer/image_io/image_io.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

namespace {

/// A pixel's height as POV-Ray 3.7 reads it, in 65536ths: a grey level to 16 bits; an 8-bit
/// colour's red as the high byte and green as the low one; a deeper colour's weighted grey.
double pixelHeight(const float* rgb, bool eightBit) {
    if (eightBit) return (std::round(rgb[0] * 255.0) * 256 + std::round(rgb[1] * 255.0)) / 65536;
    if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) return std::round(std::clamp(rgb[0], 0.0f, 1.0f) * 65535.0) / 65536;
    const double grey = std::clamp(0.297 * rgb[0] + 0.589 * rgb[1] + 0.114 * rgb[2], 0.0, 1.0);
    return std::trunc(grey * 65535) / 65536;
}

bool readImageHeights(const scene::HeightFieldDesc& desc, const scene::RenderLimits& limits,
                      HeightGrid& grid, std::string& error) {
    bool eightBit = false;
    const std::string& path = scene::fileToOpen(desc.resolvedImage, desc.image);
    std::optional<image_io::ImageBuffer> image = image_io::readImage(path, error, &eightBit, limits.maxImagePixels);
    if (!image) return false;
    if (image->width < 2 || image->height < 2) {
        error = "cannot make a HeightField of \"" + path + "\": it needs at least 2 x 2 pixels";
        return false;
    }
    grid.columns = image->width;
    grid.rows = image->height;
    grid.heights.resize(static_cast<size_t>(grid.columns) * grid.rows);
    for (int y = 0; y < image->height; ++y) {
        for (int x = 0; x < image->width; ++x) {
            const float* pixel = &image->pixels[(static_cast<size_t>(y) * image->width + x) * image->channels];
            // The image's top row is the far edge, z = 1.
            grid.heights[static_cast<size_t>(image->height - 1 - y) * grid.columns + x] =
                static_cast<float>(pixelHeight(pixel, eightBit));
        }
    }
    return true;
}

void sampleFunction(const scene::HeightFieldDesc& desc, HeightGrid& grid) {
    grid.columns = grid.rows = desc.resolution;
    grid.heights.resize(static_cast<size_t>(grid.columns) * grid.rows);
    const double step = 1.0 / (desc.resolution - 1);
    for (int j = 0; j < grid.rows; ++j) {
        for (int i = 0; i < grid.columns; ++i) {
            const double h = desc.function->at(i * step, 0, j * step);
            grid.heights[static_cast<size_t>(j) * grid.columns + i] =
                static_cast<float>(std::isnan(h) ? 0.0 : std::clamp(h, 0.0, 1.0));
        }
    }
}

} // namespace

std::shared_ptr<const HeightGrid> readHeightGrid(const scene::HeightFieldDesc& desc,
                                                 const scene::RenderLimits& limits, std::string& error) {
    auto grid = std::make_shared<HeightGrid>();
    if (desc.function) {
        sampleFunction(desc, *grid);
    } else if (!readImageHeights(desc, limits, *grid, error)) {
        return nullptr;
    }
    if (desc.smooth) grid->computeNormals();
    return grid;
}

} // namespace crt::tracer
