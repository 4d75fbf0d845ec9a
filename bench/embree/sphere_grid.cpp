// The sphere grid of bench/embree/run.sh (see bench/README.md, "Ray kernel vs Embree 3"):
// grid² spheres (RTC_GEOMETRY_TYPE_SPHERE_POINT) rendered by harness.hpp's camera, light and
// shading. Built by run.sh only; crtc does not depend on it.
#include "harness.hpp"

namespace {

struct Grid {
    int grid = 100;         ///< spheres per side: grid² spheres
    double spacing = 1.0;   ///< between neighbouring centres
    double radius = 0.45;
};

constexpr const char* kUsage = "--grid N --spacing S --radius R";

void attachGrid(RTCDevice device, RTCScene scene, const Grid& g) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    const size_t count = size_t(g.grid) * size_t(g.grid);
    auto* points = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), count));
    // Centres as run.sh writes them in CRT: x = spacing·(i − (grid−1)/2), y = radius, z = spacing·j.
    for (int i = 0; i < g.grid; ++i)
        for (int j = 0; j < g.grid; ++j) {
            float* p = points + 4 * (size_t(i) * size_t(g.grid) + size_t(j));
            p[0] = float(g.spacing * (i - (g.grid - 1) / 2.0));
            p[1] = float(g.radius);
            p[2] = float(g.spacing * j);
            p[3] = float(g.radius);
        }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

} // namespace

int main(int argc, char** argv) {
    Grid g;
    auto gridOption = [&](const std::string& name, const char* value) {
        if (name == "--grid") g.grid = std::atoi(value);
        else if (name == "--spacing") g.spacing = std::atof(value);
        else if (name == "--radius") g.radius = std::atof(value);
        else return false;
        return true;
    };
    const harness::View view = harness::parseView(argc, argv, kUsage, gridOption);
    if (g.grid < 1 || g.grid > 10000 || !(g.radius > 0)) harness::usage(argv[0], kUsage);
    return harness::run(view, "spheres " + std::to_string(size_t(g.grid) * size_t(g.grid)),
                        [&](RTCDevice device, RTCScene scene) { attachGrid(device, scene, g); });
}
