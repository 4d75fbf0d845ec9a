#include "tracer/pixel_sampler.hpp"

#include <algorithm>

namespace crt::tracer {

double PathPixel::relativeError() const {
    if (paths < 2) return 1;
    const double n = paths, mean = sumLuminance / n;
    const double variance = std::max(0.0, sumSquares / n - mean * mean) * n / (n - 1);
    return std::sqrt(variance / n) / std::max(mean, 1e-3);
}

PixelSampler::PixelSampler(const Integrator& integrator, const PathIntegrator* path, bool lens, const Camera& camera,
                           const scene::SettingsDesc& settings, const scene::MotionDesc& motion,
                           bool transparentBackground)
    : integrator_(integrator), path_(path), pathLens_(lens), camera_(camera), settings_(settings), motion_(motion),
      dofSamples_(camera.usesLens() ? std::max(settings.dofSamples, 1) : 1), bounces_(settings.bounceLimit()),
      transparentBackground_(transparentBackground) {}

void writePathPixel(const PathPixel& p, const PathAovSums& sums, int colorChannels, AovSet aovs, float* out) {
    const glm::dvec4 mean = p.mean();
    for (int c = 0; c < colorChannels; ++c) *out++ = static_cast<float>(mean[c]);
    const double n = p.paths;
    auto write = [&](const glm::dvec3& v) {
        for (int c = 0; c < 3; ++c) *out++ = static_cast<float>(v[c]);
    };
    if (aovs.has(Aov::Variance)) {
        glm::dvec3 variance(0.0);
        if (n >= 2)
            for (int c = 0; c < 3; ++c)
                variance[c] = std::max(0.0, sums.squares[c] - n * mean[c] * mean[c]) / (n * (n - 1));
        write(variance);
    }
    if (aovs.has(Aov::Albedo)) write(n > 0 ? sums.albedo / n : glm::dvec3(0.0));
    if (aovs.has(Aov::Normal)) write(n > 0 ? sums.normal / n : glm::dvec3(0.0));
}

void PixelSampler::pixel(int x, int y, int colorChannels, AovSet aovs, float* out, TraceContext& context) const {
    if (path_) {
        PathPixel p;
        PathAovSums sums;
        addPaths(x, y, p, settings_.samples, context, aovs.empty() ? nullptr : &sums);
        context.stats.addPathPixel(static_cast<uint64_t>(p.paths), p.relativeError());
        writePathPixel(p, sums, colorChannels, aovs, out);
        return;
    }
    const Color c = whittedPixel(x, y, context);
    for (int i = 0; i < colorChannels; ++i) out[i] = static_cast<float>(c[i]);
}

PixelSampler::Color PixelSampler::whittedPixel(int x, int y, TraceContext& context) const {
    uint64_t pixelIndex = static_cast<uint64_t>(y) * settings_.width + x;
    bool adaptive = settings_.antialias == scene::Antialias::Adaptive ||
                    settings_.antialias == scene::Antialias::ShowAdaptive;
    if (adaptive) {
        bool subdivides = false;
        uint32_t sampleIndex = 0;
        Color c = region(x + 0.5, y + 0.5, 1.0, 0, pixelIndex, sampleIndex, subdivides, context);
        if (settings_.antialias == scene::Antialias::ShowAdaptive && subdivides) return {1, 0, 0, 1};
        return c;
    }
    int n = std::max(settings_.supersampling, 1);
    bool jittered = settings_.antialias == scene::Antialias::Stratified;
    // One sample at the centre, the usual case: without the loop's sum and division (the
    // zero added keeps the loop's result to the bit: -0 becomes 0).
    if (n == 1 && !jittered) return Color(0.0) + sample(x + 0.5, y + 0.5, pixelIndex, 0, context);
    Color sum(0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            uint32_t k = static_cast<uint32_t>(j * n + i);
            Vec2 offset = jittered ? cellJitter(pixelIndex, k) : Vec2(0.5);
            sum += sample(x + (i + offset.x) / n, y + (j + offset.y) / n, pixelIndex, k, context);
        }
    return sum / static_cast<double>(n * n);
}

void PixelSampler::addPaths(int x, int y, PathPixel& p, int upTo, TraceContext& context, PathAovSums* sums) const {
    constexpr int kBatch = scene::SettingsDesc::kMinAdaptiveSamples;
    const uint64_t pixelIndex = static_cast<uint64_t>(y) * settings_.width + x;
    upTo = std::min(upTo, settings_.samples);
    while (!p.settled && p.paths < upTo) {
        context.rng = SampleRng::sequence(settings_.seed, pixelIndex, static_cast<uint32_t>(p.paths));
        context.time = shutterTime(pixelIndex, static_cast<uint32_t>(p.paths));
        const Vec2 offset = context.rng.uniform2();
        FirstSurface first;
        Color c(0.0); // black and transparent where the camera has no ray
        if (camera_.sees(x + offset.x, y + offset.y)) {
            const Vec2 lens = pathLens_ ? context.rng.uniform2() : Vec2(0.0);
            const Ray ray = cameraRay(x + offset.x, y + offset.y, pathLens_ ? &lens : nullptr, context.time);
            ++context.stats.cameraRays;
            c = path_->traceCamera(ray, transparentBackground_, context, sums ? &first : nullptr);
        }
        if (sums) {
            sums->squares += glm::dvec3(c) * glm::dvec3(c);
            sums->albedo += first.albedo;
            sums->normal += first.normal;
        }
        p.sum += c;
        const double l = luminance(Vec3(c));
        p.sumLuminance += l, p.sumSquares += l * l;
        ++p.paths;
        p.settled = p.paths >= settings_.samples ||
                    (settings_.targetError > 0 && p.paths % kBatch == 0 && p.relativeError() <= settings_.targetError);
    }
}

/// Its own stream of the pixel's random numbers, apart from the stream the sample then traces
/// with, so the position is not correlated with the sample's light and lens choices.
Vec2 PixelSampler::cellJitter(uint64_t pixelIndex, uint32_t k) const {
    constexpr uint64_t kJitterStream = uint64_t{1} << 40;
    return SampleRng(settings_.seed, pixelIndex, kJitterStream + k).uniform2();
}

/// The four quadrant centres, a quadrant subdivided while its samples disagree by more than
/// the threshold, up to aadepth levels; the area-weighted mean.
PixelSampler::Color PixelSampler::region(double cx, double cy, double size, int level, uint64_t pixelIndex,
                                         uint32_t& sampleIndex, bool& subdivides, TraceContext& context) const {
    Color corners[4];
    double q = size / 4;
    const double offsets[4][2] = {{-q, -q}, {q, -q}, {-q, q}, {q, q}};
    for (int k = 0; k < 4; ++k)
        corners[k] = sample(cx + offsets[k][0], cy + offsets[k][1], pixelIndex, sampleIndex++, context);
    double spread = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
            Color d = glm::abs(corners[a] - corners[b]);
            spread = std::max({spread, d.x, d.y, d.z, d.w});
        }
    if (spread > settings_.aaThreshold && level < settings_.aaDepth) {
        subdivides = true;
        if (settings_.antialias == scene::Antialias::ShowAdaptive) return corners[0];
        for (int k = 0; k < 4; ++k)
            corners[k] = region(cx + offsets[k][0], cy + offsets[k][1], size / 2, level + 1, pixelIndex, sampleIndex,
                                subdivides, context);
    }
    return (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
}

PixelSampler::Color PixelSampler::sample(double u, double v, uint64_t pixelIndex, uint32_t sampleIndex,
                                         TraceContext& context) const {
    context.rng = SampleRng(settings_.seed, pixelIndex, sampleIndex);
    if (!camera_.sees(u, v)) return Color(0.0); // black and transparent
    const uint32_t dofSamples = static_cast<uint32_t>(dofSamples_);
    if (dofSamples <= 1) {
        ++context.stats.cameraRays;
        context.time = shutterTime(pixelIndex, sampleIndex);
        return integrator_.traceCamera(cameraRay(u, v, nullptr, context.time), bounces_, transparentBackground_,
                                       context);
    }
    // Depth of field: a low-discrepancy set of lens points, shifted per pixel sample.
    Vec2 shift = context.rng.uniform2();
    Color sum(0.0);
    for (uint32_t k = 0; k < dofSamples; ++k) {
        Vec2 lens = hammersley(k, dofSamples, shift);
        ++context.stats.cameraRays;
        context.time = shutterTime(pixelIndex, sampleIndex * dofSamples + k);
        sum += integrator_.traceCamera(cameraRay(u, v, &lens, context.time), bounces_, transparentBackground_, context);
    }
    return sum / static_cast<double>(dofSamples_);
}

/// The van der Corput sequence, shifted by a number of the pixel's own (as the lens points
/// are): a pixel's samples spread evenly over the shutter, and neighbours differ.
double PixelSampler::shutterTime(uint64_t pixelIndex, uint32_t i) const {
    if (motion_.empty()) return 0;
    constexpr uint64_t kShutterStream = uint64_t{1} << 41;
    const double time = radicalInverse2(i) + SampleRng(settings_.seed, pixelIndex, kShutterStream).uniform();
    return time >= 1 ? time - 1 : time;
}

Ray PixelSampler::cameraRay(double u, double v, const Vec2* lens, double time) const {
    auto through = [&](const Camera& camera) {
        Ray ray = lens ? camera.lensRay(u, v, *lens) : camera.ray(u, v);
        ray.time = time;
        return ray;
    };
    if (motion_.cameras.empty()) return through(camera_);
    return through(Camera(cameraAt(motion_.cameras, time), settings_.width, settings_.height, settings_.dofSamples));
}

} // namespace crt::tracer
