// Piecewise-constant distributions.
#include "tracer/distribution.hpp"

#include <algorithm>
#include <cmath>

namespace crt::tracer {

Distribution1D::Distribution1D(std::vector<double> values) : values_(std::move(values)) {
    const size_t n = values_.size();
    cumulative_.assign(n + 1, 0.0);
    for (size_t i = 0; i < n; ++i) cumulative_[i + 1] = cumulative_[i] + values_[i] / static_cast<double>(n);
    mean_ = n > 0 ? cumulative_[n] : 0;
    for (size_t i = 1; i <= n; ++i)
        cumulative_[i] = mean_ > 0 ? cumulative_[i] / mean_ : static_cast<double>(i) / static_cast<double>(n);
}

double Distribution1D::sample(double u, size_t& cell, double& pdf) const {
    // The last cell whose cumulative start is at most u (cells of zero chance never are).
    const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
    cell = std::min(static_cast<size_t>(std::max<std::ptrdiff_t>(above - cumulative_.begin() - 1, 0)), values_.size() - 1);
    const double width = cumulative_[cell + 1] - cumulative_[cell];
    const double within = width > 0 ? (u - cumulative_[cell]) / width : 0.5;
    pdf = this->pdf(cell);
    return std::min((static_cast<double>(cell) + within) / static_cast<double>(values_.size()), std::nextafter(1.0, 0.0));
}

Distribution2D::Distribution2D(const std::vector<double>& values, size_t width, size_t height)
    : marginal_({}), width_(width), height_(height) {
    std::vector<double> rowMeans;
    rows_.reserve(height);
    for (size_t y = 0; y < height; ++y) {
        rows_.emplace_back(std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(y * width),
                                               values.begin() + static_cast<std::ptrdiff_t>((y + 1) * width)));
        rowMeans.push_back(rows_.back().mean());
    }
    marginal_ = Distribution1D(std::move(rowMeans));
}

Vec2 Distribution2D::sample(const Vec2& u, double& pdf) const {
    size_t row = 0, column = 0;
    double rowPdf = 0, columnPdf = 0;
    const double v = marginal_.sample(u.y, row, rowPdf);
    const double x = rows_[row].sample(u.x, column, columnPdf);
    pdf = rowPdf * columnPdf;
    return {x, v};
}

double Distribution2D::pdf(const Vec2& uv) const {
    const size_t column = std::min(static_cast<size_t>(std::max(uv.x, 0.0) * static_cast<double>(width_)), width_ - 1);
    const size_t row = std::min(static_cast<size_t>(std::max(uv.y, 0.0) * static_cast<double>(height_)), height_ - 1);
    return marginal_.pdf(row) * rows_[row].pdf(column);
}

} // namespace crt::tracer
