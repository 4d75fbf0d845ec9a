// The panorama as a light: its density of directions is a density (it integrates to one over
// the sphere), the one sample() draws by, and importance-sampled estimates of the light it
// sends converge on the integral of the panorama.
#include "tracer/environment_light.hpp"
#include "tracer/lights.hpp"
#include "tracer/sampling.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;

namespace {

/// A dim sky above a dark ground, with a small bright sun: what importance sampling is for.
Image sunnySky(int width, int height) {
    Image image;
    image.width = width, image.height = height;
    image.rgb.assign(static_cast<size_t>(width) * height * 3, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = &image.rgb[3 * (static_cast<size_t>(y) * width + x)];
            const bool sun = x >= width / 3 && x < width / 3 + 2 && y >= height / 4 && y < height / 4 + 2;
            const float value = sun ? 500.0f : y < height / 2 ? 0.4f : 0.05f;
            p[0] = value, p[1] = value * 0.9f, p[2] = value * 0.8f;
        }
    return image;
}

/// ∫ f(ω) dω over the sphere, as ∫∫ f sin θ dθ dφ by the midpoint rule on n × 2n cells.
template <typename F> double sphereIntegral(F&& f, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double theta = kPi * (i + 0.5) / n, z = std::cos(theta), r = std::sin(theta);
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = kPi * (j + 0.5) / n;
            sum += f(Vec3(r * std::cos(phi), z, r * std::sin(phi))) * r;
        }
    }
    return sum * (kPi / n) * (kPi / n);
}

} // namespace

TEST_CASE("environment light: the density of directions integrates to one over the sphere", "[render][path]") {
    const Image image = sunnySky(64, 32);
    scene::BackgroundDesc desc;
    desc.kind = scene::BackgroundKind::Image;
    desc.angle = 0.7;
    const Background background(desc, &image);
    const EnvironmentLight light(background);
    REQUIRE(light.active());
    CHECK(sphereIntegral([&](const Vec3& d) { return light.pdf(d); }, 800) == Approx(1).epsilon(2e-3));
}

TEST_CASE("environment light: sampled directions carry the density pdf() gives them", "[render][path]") {
    const Image image = sunnySky(64, 32);
    scene::BackgroundDesc desc;
    desc.kind = scene::BackgroundKind::Image;
    desc.angle = -1.3;
    const Background background(desc, &image);
    const EnvironmentLight light(background);
    SampleRng rng(1, 2, 3);
    for (int i = 0; i < 2000; ++i) {
        double pdf = 0;
        const Vec3 d = light.sample(rng.uniform2(), pdf);
        INFO("sample " << i << " direction " << d.x << " " << d.y << " " << d.z);
        CHECK(glm::length(d) == Approx(1).epsilon(1e-12));
        CHECK(pdf == Approx(light.pdf(d)).epsilon(1e-9));
    }
}

TEST_CASE("environment light: importance-sampled light converges on the panorama's integral", "[render][path]") {
    // E[L(ω) / pdf(ω)] = ∫ L dω: the estimate of the power the sky sends through a point.
    const Image image = sunnySky(64, 32);
    scene::BackgroundDesc desc;
    desc.kind = scene::BackgroundKind::Image;
    const Background background(desc, &image);
    const EnvironmentLight light(background);
    const double exact = sphereIntegral([&](const Vec3& d) { return luminance(background.radiance(d)); }, 1000);
    SampleRng rng(4, 5, 6);
    constexpr int kSamples = 20000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < kSamples; ++i) {
        double pdf = 0;
        const Vec3 d = light.sample(rng.uniform2(), pdf);
        const double value = pdf > 0 ? luminance(background.radiance(d)) / pdf : 0;
        sum += value, sum2 += value * value;
    }
    const double mean = sum / kSamples, error = std::sqrt((sum2 / kSamples - mean * mean) / kSamples);
    INFO("mean " << mean << " standard error " << error << " exact " << exact);
    CHECK(std::abs(mean - exact) < 3 * error + 1e-3 * exact);
    // Importance sampling is what makes it converge: the error is far below uniform sampling's.
    CHECK(error < 0.05 * exact);
}
