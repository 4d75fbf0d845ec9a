// Counters of the work a render did, per thread and summed.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace crt::tracer {

struct RayStats {
    uint64_t cameraRays = 0;
    uint64_t reflectionRays = 0;
    uint64_t refractionRays = 0;
    uint64_t shadowRays = 0;
    uint64_t nodesVisited = 0;      ///< BVH nodes whose box was tested
    uint64_t intersectionTests = 0; ///< primitive line-crossing queries
    uint64_t cachedFrames = 0;      ///< animation frames reused because the scene did not change
    // The path integrator's pixels: how many paths each took and how far each is from converged.
    uint64_t pathPixels = 0;
    uint64_t fewestPaths = std::numeric_limits<uint64_t>::max(); ///< of one pixel
    uint64_t mostPaths = 0;                                      ///< of one pixel
    /// Σ over the pixels of (the relative standard error of its mean)², each at most 1, in
    /// units of 2⁻³²: an integer, so that it is summed over threads and ranks exactly.
    uint64_t squaredErrors = 0;

    RayStats& operator+=(const RayStats& o) {
        const auto sums = summed(), other = o.summed();
        std::array<uint64_t, kSummed> total{};
        for (size_t i = 0; i < kSummed; ++i) total[i] = sums[i] + other[i];
        *this = fromCounters(total, {std::max(mostPaths, o.mostPaths), ~std::min(fewestPaths, o.fewestPaths)});
        return *this;
    }
    uint64_t totalRays() const { return cameraRays + reflectionRays + refractionRays + shadowRays; }

    /// A path-traced pixel's count of paths and the relative standard error of its mean.
    void addPathPixel(uint64_t paths, double relativeError) {
        ++pathPixels;
        fewestPaths = std::min(fewestPaths, paths);
        mostPaths = std::max(mostPaths, paths);
        const double squared = std::min(relativeError * relativeError, 1.0);
        squaredErrors += static_cast<uint64_t>(std::llround(std::ldexp(squared, 32)));
    }
    /// The root mean square of the pixels' relative standard errors.
    double imageRelativeError() const {
        return pathPixels > 0 ? std::sqrt(std::ldexp(static_cast<double>(squaredErrors), -32) / pathPixels) : 0;
    }

    /// The counters as they travel between processes, in one order: those summed, then those
    /// whose greatest is taken (the most paths, and the complement of the fewest).
    static constexpr size_t kSummed = 9, kGreatest = 2;
    std::array<uint64_t, kSummed> summed() const {
        return {cameraRays,        reflectionRays, refractionRays, shadowRays,   nodesVisited,
                intersectionTests, cachedFrames,   pathPixels,     squaredErrors};
    }
    std::array<uint64_t, kGreatest> greatest() const { return {mostPaths, ~fewestPaths}; }
    static RayStats fromCounters(const std::array<uint64_t, kSummed>& s, const std::array<uint64_t, kGreatest>& g) {
        RayStats r;
        r.cameraRays = s[0], r.reflectionRays = s[1], r.refractionRays = s[2], r.shadowRays = s[3];
        r.nodesVisited = s[4], r.intersectionTests = s[5], r.cachedFrames = s[6];
        r.pathPixels = s[7], r.squaredErrors = s[8];
        r.mostPaths = g[0], r.fewestPaths = ~g[1];
        return r;
    }
};

} // namespace crt::tracer
