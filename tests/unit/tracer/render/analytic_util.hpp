// Independent re-statements of spec §6 (camera rays, ray–shape hits) for the analytic render tests.
//
// Nothing here calls the renderer's own camera or geometry: the tests compare render's
// pixels with values derived from the specification alone.
#pragma once

#include "tracer/renderer.hpp"
#include "scene/scene_desc.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <optional>

namespace crt::tracer::test {

using DVec3 = glm::dvec3;

constexpr double kTestPi = 3.14159265358979323846;

struct TestRay {
    DVec3 origin;
    DVec3 dir; ///< unit length
    DVec3 at(double t) const { return origin + t * dir; }
};

/// Spec §6 primary ray through the centre of pixel (x, y) (supersampling 1, pinhole):
/// normalize(f + (2u/W − 1)·tan(fov/2)·(W/H)·r + (1 − 2v/H)·tan(fov/2)·up').
inline TestRay specCameraRay(const scene::CameraDesc& cam, int width, int height, int x, int y) {
    DVec3 f = glm::normalize(cam.pointing - cam.position);
    // Left-handed: with y up and z forward, right is +x, which is up × forward.
    DVec3 r = glm::normalize(glm::cross(cam.up, f));
    DVec3 up = glm::cross(f, r);
    double u = x + 0.5, v = y + 0.5;
    double t = std::tan(cam.fov * kTestPi / 360.0);
    double aspect = static_cast<double>(width) / height;
    DVec3 d = f + (2 * u / width - 1) * t * aspect * r + (1 - 2 * v / height) * t * up;
    return {cam.position, glm::normalize(d)};
}

/// Nearest hit distance of a ray with a sphere (outside the sphere), if any; `margin` > 0
/// rejects grazing rays whose closest approach lies within `margin` of the silhouette.
inline std::optional<double> hitSphere(const TestRay& ray, DVec3 center, double radius, double margin = 0) {
    DVec3 f = ray.origin - center;
    double b = glm::dot(f, ray.dir);
    DVec3 closest = f - b * ray.dir;
    double miss2 = glm::dot(closest, closest);
    double h = radius * radius - miss2;
    if (h < 0) return std::nullopt;
    if (margin > 0 && std::abs(std::sqrt(miss2) - radius) < margin) return std::nullopt;
    double t = -b - std::sqrt(h);
    if (t <= 0) return std::nullopt;
    return t;
}

/// Hit distance with the plane through `point` with normal `normal`, if in front of the ray.
inline std::optional<double> hitPlane(const TestRay& ray, DVec3 normal, DVec3 point) {
    double denom = glm::dot(ray.dir, normal);
    if (denom == 0) return std::nullopt;
    double t = glm::dot(point - ray.origin, normal) / denom;
    if (t <= 0) return std::nullopt;
    return t;
}

/// Refracts unit `d` through a surface with unit normal `n` facing against `d`, from index
/// n1 to n2 (Snell: n1·sin θi = n2·sin θt); nullopt on total internal reflection.
inline std::optional<DVec3> snellRefract(DVec3 d, DVec3 n, double n1, double n2) {
    double cosI = -glm::dot(d, n);
    DVec3 tangential = d + cosI * n;                 // the component along the surface, length sin θi
    DVec3 tangentialOut = tangential * (n1 / n2);    // sin θt = (n1/n2) sin θi, same plane
    double sin2T = glm::dot(tangentialOut, tangentialOut);
    if (sin2T >= 1) return std::nullopt;
    return tangentialOut - std::sqrt(1 - sin2T) * n; // onward, away from the surface
}

/// Unpolarised Fresnel reflectance (Rs + Rp)/2 for light from index n1 into n2 at incidence cos θi.
inline double fresnelReflectance(double cosI, double n1, double n2) {
    double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1 - cosI * cosI));
    if (sinT >= 1) return 1;
    double cosT = std::sqrt(1 - sinT * sinT);
    double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
    return 0.5 * (rs * rs + rp * rp);
}

/// Renders and requires success; `threads` 0 means all cores.
inline PixelBuffer renderOk(const scene::SceneDesc& desc, int threads = 0) {
    RenderJob job;
    job.threads = threads;
    PixelBuffer image(desc.settings.width, desc.settings.height);
    size_t pixels = 0;
    job.onTileDone = [&](const TileResult& tile) {
        image.place(tile);
        pixels += static_cast<size_t>(tile.tile.width()) * tile.tile.height();
    };
    RenderOutcome outcome = render(desc, job);
    INFO(outcome.error);
    REQUIRE(outcome.ok);
    REQUIRE(pixels == static_cast<size_t>(desc.settings.width) * desc.settings.height);
    return image;
}

inline DVec3 pixelAt(const PixelBuffer& image, int x, int y) {
    const float* p = &image.pixels[3 * (static_cast<size_t>(y) * image.width + x)];
    return {p[0], p[1], p[2]};
}

inline DVec3 rgbOf(const scene::Color& c) { return {c.r, c.g, c.b}; }

/// Largest per-channel absolute difference.
inline double maxDifference(DVec3 a, DVec3 b) {
    DVec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

/// A parallel light from `from` towards `pointing` (by default white, towards the origin).
inline scene::LightDesc parallelLight(DVec3 from, DVec3 pointing = DVec3(0.0),
                                      scene::Color color = scene::Color{1, 1, 1, 1}) {
    scene::LightDesc l;
    l.kind = scene::LightKind::Parallel;
    l.from = from;
    l.pointing = pointing;
    l.color = color;
    return l;
}

/// A scene with a black background and no lights, the given camera and size.
inline scene::SceneDesc blankScene(int width, int height, const scene::CameraDesc& camera) {
    scene::SceneDesc desc;
    desc.settings.width = width;
    desc.settings.height = height;
    desc.camera = camera;
    desc.camera.focalDistance = glm::length(camera.pointing - camera.position);
    desc.background.color = scene::Color{0, 0, 0, 1};
    return desc;
}

inline scene::CameraDesc lookAt(DVec3 position, DVec3 pointing, double fov) {
    scene::CameraDesc c;
    c.position = position;
    c.pointing = pointing;
    c.fov = fov;
    return c;
}

} // namespace crt::tracer::test
