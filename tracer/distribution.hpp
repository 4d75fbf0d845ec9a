// Piecewise-constant distributions: choosing a cell of a grid with a chance proportional to
// its value (pbrt's Distribution1D and Distribution2D).
#pragma once

#include "tracer/geometry/ray.hpp"

#include <vector>

namespace crt::tracer {

/// Over n cells of [0, 1), each of width 1/n.
class Distribution1D {
public:
    /// `values` non-negative; all zero (or none) gives a uniform distribution.
    explicit Distribution1D(std::vector<double> values);

    size_t size() const { return values_.size(); }
    /// The sum of the values over n: the mean (the normaliser of the density).
    double mean() const { return mean_; }
    /// A point x in [0, 1) by u uniform in [0, 1); its cell in `cell`, its density in `pdf`.
    double sample(double u, size_t& cell, double& pdf) const;
    /// The density at a point of cell `cell`.
    double pdf(size_t cell) const { return mean_ > 0 ? values_[cell] / mean_ : 1; }

private:
    std::vector<double> values_;
    std::vector<double> cumulative_; ///< n + 1 values from 0 to 1
    double mean_ = 0;
};

/// Over a width × height grid of [0, 1)²: a row by the rows' sums, then a column in it.
class Distribution2D {
public:
    /// `values`: row-major, top row first.
    Distribution2D(const std::vector<double>& values, size_t width, size_t height);

    /// A point (u, v) by a uniform point of [0, 1)², and its density (over [0, 1)²).
    Vec2 sample(const Vec2& u, double& pdf) const;
    double pdf(const Vec2& uv) const;

private:
    std::vector<Distribution1D> rows_;
    Distribution1D marginal_;
    size_t width_, height_;
};

} // namespace crt::tracer
