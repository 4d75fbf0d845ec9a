// Shared pieces of the numerical-stability suite: 8-bit comparison, flat materials, zoomed
// cameras, mesh files and robust classification of pixels against an analytic silhouette.
#pragma once

#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace crt::tracer::stress {

using test::DVec3;
using test::TestRay;

/// The 8-bit codes an output file would hold (gamma 1).
inline std::vector<int> quantised(const PixelBuffer& image) {
    std::vector<int> codes(image.pixels.size());
    for (size_t i = 0; i < codes.size(); ++i) {
        double v = std::clamp(static_cast<double>(image.pixels[i]), 0.0, 1.0);
        codes[i] = static_cast<int>(std::floor(255 * v + 0.5));
    }
    return codes;
}

/// A number for messages, with three significant digits.
inline std::string number(double v) {
    std::ostringstream out;
    out << std::setprecision(3) << v;
    return out.str();
}

/// How two images differ as 8-bit codes.
struct ImageDiff {
    int worst = 0;   ///< largest per-channel difference, in 1/255
    int over = 0;    ///< pixels whose largest channel difference exceeds the slack
    int worstX = -1; ///< where the largest difference is
    int worstY = -1;
    std::string where; ///< the first few pixels over the slack, "x,y (Δ)"
};

inline ImageDiff compare8bit(const PixelBuffer& got, const PixelBuffer& want, int slack = 1) {
    std::vector<int> a = quantised(got), b = quantised(want);
    REQUIRE(a.size() == b.size());
    ImageDiff diff;
    for (size_t p = 0; p + 2 < a.size(); p += 3) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[p + c] - b[p + c]));
        if (d > diff.worst) {
            diff.worst = d;
            diff.worstX = static_cast<int>(p / 3) % got.width;
            diff.worstY = static_cast<int>(p / 3) / got.width;
        }
        if (d > slack && ++diff.over <= 8) {
            int pixel = static_cast<int>(p / 3);
            diff.where += std::to_string(pixel % got.width) + "," +
                          std::to_string(pixel / got.width) + " (" + std::to_string(d) + ") ";
        }
    }
    return diff;
}

/// Spec §6 primary ray through the image point (u, v) in pixel units (centres at +0.5): the
/// same formula as test::specCameraRay, at any sub-pixel position.
inline TestRay cameraRayAt(const scene::CameraDesc& cam, int width, int height, double u,
                           double v) {
    DVec3 f = glm::normalize(cam.pointing - cam.position);
    DVec3 r = glm::normalize(glm::cross(cam.up, f));
    DVec3 up = glm::cross(f, r);
    double t = std::tan(cam.fov * test::kTestPi / 360.0);
    double aspect = static_cast<double>(width) / height;
    DVec3 d = f + (2 * u / width - 1) * t * aspect * r + (1 - 2 * v / height) * t * up;
    return {cam.position, glm::normalize(d)};
}

enum class Coverage { Inside, Outside, Edge };

/// Where pixel (x, y) lies against an analytic silhouette: Inside when its centre ray and eight
/// rays `delta` pixels around it all hit, Outside when all miss, Edge otherwise. The probes
/// keep the verdict away from rounding in the analytic test itself, so an Inside pixel is one
/// the renderer must hit and an Outside one it must miss.
template <typename Hits>
Coverage coverage(const scene::SceneDesc& desc, int x, int y, double delta, const Hits& hits) {
    int hit = 0, count = 0;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            TestRay ray = cameraRayAt(desc.camera, desc.settings.width, desc.settings.height,
                                      x + 0.5 + i * delta, y + 0.5 + j * delta);
            hit += hits(ray) ? 1 : 0;
            ++count;
        }
    }
    return hit == count ? Coverage::Inside : hit == 0 ? Coverage::Outside : Coverage::Edge;
}

/// A material whose pixels are `emission` wherever it is hit, whatever the lights (no diffuse
/// term); with `reflectivity` > 0 a reflection of a black background adds nothing, so any
/// excess over `emission` is the surface seeing itself.
inline int32_t flatMaterial(test::SceneMaker& m, scene::Color emission, double reflectivity = 0) {
    ShadingMaterial mat;
    mat.color = scene::Color{0.5, 0.5, 0.5, 1};
    mat.diffuse = 0;
    mat.emission = emission;
    mat.reflectivity = reflectivity;
    return m.material(mat);
}

/// A plain Lambertian material (diffuse 1): a lit pixel is exactly color × (n · l).
inline int32_t lambertMaterial(test::SceneMaker& m, scene::Color color) {
    ShadingMaterial mat;
    mat.color = color;
    return m.material(mat);
}

/// A pinhole camera at `position` aimed at `target`, whose image is `windowHeight` world units
/// high at the target's distance: a small window zooms onto a silhouette.
inline scene::CameraDesc zoomedCamera(DVec3 position, DVec3 target, double windowHeight) {
    double distance = glm::length(target - position);
    double fov = 2 * std::atan(0.5 * windowHeight / distance) * 180 / test::kTestPi;
    return test::lookAt(position, target, fov);
}

/// A parallel light arriving from direction `toLight` (unit vector towards the light).
inline scene::LightDesc parallelLight(DVec3 toLight, scene::Color color = {1, 1, 1, 1}) {
    scene::LightDesc light;
    light.kind = scene::LightKind::Parallel;
    light.from = toLight;
    light.pointing = DVec3(0.0);
    light.color = color;
    return light;
}

/// An OBJ file written for one test into the system's temporary folder, removed afterwards
/// (named with the process id: ctest runs test cases as parallel processes).
class TempObjFile {
  public:
    TempObjFile(const std::string& name, const std::vector<DVec3>& vertices,
                const std::vector<std::array<int, 3>>& triangles)
        : path_(std::filesystem::temp_directory_path() /
                ("crt_stress_" + std::to_string(::getpid()) + "_" + name + ".obj")) {
        std::ofstream out(path_);
        out.precision(17); // round-trips every double: shared vertices stay bit-identical
        for (const DVec3& v : vertices) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
        for (const auto& t : triangles)
            out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
    ~TempObjFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TempObjFile(const TempObjFile&) = delete;
    TempObjFile& operator=(const TempObjFile&) = delete;

    std::string path() const { return path_.string(); }

  private:
    std::filesystem::path path_;
};

} // namespace crt::tracer::stress
