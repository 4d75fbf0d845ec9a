// The panorama's luminance as a distribution of directions.
#include "tracer/environment_light.hpp"

#include "tracer/lights.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

EnvironmentLight::EnvironmentLight(const Background& background) : background_(background) {
    const Image* image = background.panorama();
    if (!image) return;
    // Each cell takes the brightest texel of its block and of the texels around it: the
    // panorama is read with bilinear filtering, which spreads a texel half a texel into its
    // neighbours, and the density must not be small where the light is not. Each cell is then
    // weighed by sin θ, the share of the sphere its row of the equirectangular map covers.
    const int block = std::max(1, (image->width + kMaxColumns - 1) / kMaxColumns);
    const int columns = (image->width + block - 1) / block, rows = (image->height + block - 1) / block;
    std::vector<double> values(static_cast<size_t>(columns) * static_cast<size_t>(rows), 0.0);
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            double brightest = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int tx = (x + dx + image->width) % image->width; // u wraps
                    const int ty = std::clamp(y + dy, 0, image->height - 1); // v clamps
                    brightest = std::max(brightest, luminance(image->texel(tx, ty)));
                }
            double& cell = values[static_cast<size_t>(y / block) * columns + static_cast<size_t>(x / block)];
            cell = std::max(cell, brightest);
        }
    for (int row = 0; row < rows; ++row) {
        const double sinTheta = std::sin((row + 0.5) / rows * kPi);
        for (int column = 0; column < columns; ++column) values[static_cast<size_t>(row) * columns + column] *= sinTheta;
    }
    distribution_.emplace(values, static_cast<size_t>(columns), static_cast<size_t>(rows));
}

Vec3 EnvironmentLight::sample(const Vec2& u, double& pdf) const {
    double uvPdf = 0;
    const Vec2 uv = distribution_->sample(u, uvPdf);
    const double sinTheta = std::sin(uv.y * kPi);
    pdf = sinTheta > 0 ? uvPdf / (2 * kPi * kPi * sinTheta) : 0;
    return background_.panoramaDirection(uv);
}

double EnvironmentLight::pdf(const Vec3& d) const {
    if (!distribution_) return 0;
    const Vec2 uv = background_.panoramaCoordinates(d);
    const double sinTheta = std::sin(uv.y * kPi);
    return sinTheta > 0 ? distribution_->pdf(uv) / (2 * kPi * kPi * sinTheta) : 0;
}

} // namespace crt::tracer
