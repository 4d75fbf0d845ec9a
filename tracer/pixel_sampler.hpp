// What one pixel of the image is: its camera samples (grid, stratified, adaptive, depth of
// field) under the Whitted integrator, or its paths under the path integrator.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/aov.hpp"
#include "tracer/camera.hpp"
#include "tracer/integrator.hpp"
#include "tracer/path_integrator.hpp"

namespace crt::tracer {

/// The running sums of a path-traced pixel: what it keeps between the passes of a progressive
/// render. Taking its paths in several calls gives the same bits as taking them in one.
struct PathPixel {
    glm::dvec4 sum{0.0};
    double sumLuminance = 0, sumSquares = 0;
    int paths = 0;
    bool settled = false; ///< at its target error, or at the most paths the settings allow

    glm::dvec4 mean() const { return paths > 0 ? sum / static_cast<double>(paths) : glm::dvec4(0.0); }
    /// The standard error of the mean luminance relative to the mean, or to 1/1000 where it
    /// is darker, so that black pixels settle; 1 for fewer than two paths.
    double relativeError() const;
};

/// The sums of a path-traced pixel's paths its AOVs are made of.
struct PathAovSums {
    glm::dvec3 squares{0.0}; ///< of the colour, channel by channel
    glm::dvec3 albedo{0.0}, normal{0.0};
};

/// Writes a path-traced pixel: its `colorChannels` means (RGB, or RGB and alpha), then each
/// AOV of `aovs` from `sums`: the variance of the mean of each colour channel (0 for a single
/// path), and the mean albedo and normal of what its paths first met (FirstSurface; 0 for a
/// path that met nothing such).
void writePathPixel(const PathPixel& pixel, const PathAovSums& sums, int colorChannels, AovSet aovs, float* out);

/// Computes pixels; one per thread, sharing the read-only scene.
class PixelSampler {
public:
    /// RGB and alpha: samples are averaged in all four, so edges against a transparent
    /// background get partial alpha.
    using Color = glm::dvec4;

    /// `path`: the path integrator, when the scene chose it; `lens`: whether its paths start
    /// on the lens (an aperture); `motion`: what moves while the shutter is open (each camera
    /// sample then has its time within it).
    PixelSampler(const Integrator& integrator, const PathIntegrator* path, bool lens, const Camera& camera,
                 const scene::SettingsDesc& settings, const scene::MotionDesc& motion, bool transparentBackground);

    /// Writes the pixel's color and, with `colorChannels` 4, alpha (coverage; the color is
    /// premultiplied by it); then, for a path-traced pixel, its AOVs.
    void pixel(int x, int y, int colorChannels, AovSet aovs, float* out, TraceContext& context) const;

    /// Path tracing: adds paths to the pixel until it has `upTo` (at most the settings'
    /// `samples`), or until its target error is reached; checked every kMinAdaptiveSamples
    /// paths, so the count does not hang on the noise of a single one. `sums` (optional) gets
    /// what the AOVs need.
    void addPaths(int x, int y, PathPixel& pixel, int upTo, TraceContext& context,
                  PathAovSums* sums = nullptr) const;

private:
    Color whittedPixel(int x, int y, TraceContext& context) const;
    /// Stratified sample `k`'s place in its grid cell, in [0, 1)².
    Vec2 cellJitter(uint64_t pixelIndex, uint32_t k) const;
    /// Spec §6 "adaptive": a region of the pixel, subdivided while its samples disagree.
    Color region(double cx, double cy, double size, int level, uint64_t pixelIndex, uint32_t& sampleIndex,
                 bool& subdivides, TraceContext& context) const;
    Color sample(double u, double v, uint64_t pixelIndex, uint32_t sampleIndex, TraceContext& context) const;
    /// The time within the shutter of the pixel's camera sample `i` (0 when nothing moves).
    double shutterTime(uint64_t pixelIndex, uint32_t i) const;
    /// The camera's ray through image point (u, v) at `time` (from the lens point `lens`, if
    /// given), where the camera is then.
    Ray cameraRay(double u, double v, const Vec2* lens, double time) const;

    const Integrator& integrator_;
    const PathIntegrator* path_;
    bool pathLens_;
    const Camera& camera_;
    const scene::SettingsDesc& settings_;
    const scene::MotionDesc& motion_;
    int dofSamples_;
    int bounces_; ///< reflections and refractions a camera ray's path may take in all
    bool transparentBackground_;
};

} // namespace crt::tracer
