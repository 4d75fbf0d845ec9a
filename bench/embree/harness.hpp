// What the Embree programs of bench/embree/run.sh share (see bench/README.md, "Ray kernel vs
// Embree 3"): the view given on the command line, a pinhole camera with crtc's conventions,
// a point light, and per pixel one camera ray (rtcIntersect1) and, where the surface faces
// the light, one shadow ray (rtcOccluded1), shaded with ambient + Lambert as crtc's plain
// diffuse material is. Each program only builds its geometry; the view's numbers come from
// the command line, so the script that writes the CRT scene is the only place they are set.
//
// run() prints rays by kind, BVH build and render seconds, the render rate and the peak
// resident memory, one "key value" per line.
#pragma once

#include <embree3/rtcore.h>

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace harness {

struct Vec {
    float x, y, z;
};
inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator*(float s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(Vec a, Vec b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec normalize(Vec a) { return (1.0f / std::sqrt(dot(a, a))) * a; }

struct View {
    int width = 800, height = 600, threads = 1;
    Vec eye{0, 0, 0}, target{0, 0, 1}, light{0, 0, 0};
    double fov = 40;  ///< vertical, degrees
    std::string ppm;  ///< optional image, to compare with crtc's
};

/// The options of a program besides the view's, for its usage line ("--grid N ...").
using ExtraOption = std::function<bool(const std::string& name, const char* value)>;

[[noreturn]] inline void usage(const char* self, const char* extraUsage) {
    std::fprintf(stderr,
                 "usage: %s %s --size WxH --threads T\n"
                 "          --eye X,Y,Z --target X,Y,Z --fov DEG --light X,Y,Z [--ppm FILE]\n",
                 self, extraUsage);
    std::exit(2);
}

inline Vec parseVec(const char* self, const char* extraUsage, const char* text) {
    Vec v;
    if (std::sscanf(text, "%f,%f,%f", &v.x, &v.y, &v.z) != 3) usage(self, extraUsage);
    return v;
}

/// The view from `--name value` pairs; the others go to `extra`, which returns false for a
/// name it does not know.
inline View parseView(int argc, char** argv, const char* extraUsage, const ExtraOption& extra) {
    View o;
    const char* self = argv[0];
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) usage(self, extraUsage);
        const char* value = argv[++i];
        if (arg == "--size") {
            if (std::sscanf(value, "%dx%d", &o.width, &o.height) != 2) usage(self, extraUsage);
        } else if (arg == "--threads") o.threads = std::atoi(value);
        else if (arg == "--eye") o.eye = parseVec(self, extraUsage, value);
        else if (arg == "--target") o.target = parseVec(self, extraUsage, value);
        else if (arg == "--light") o.light = parseVec(self, extraUsage, value);
        else if (arg == "--fov") o.fov = std::atof(value);
        else if (arg == "--ppm") o.ppm = value;
        else if (!extra(arg, value)) usage(self, extraUsage);
    }
    // Bounded like crtc's own limits, so a typo cannot ask for terabytes.
    if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384 || o.threads < 1 ||
        o.threads > 256)
        usage(self, extraUsage);
    return o;
}

/// crtc's pinhole camera (tracer/camera.cpp): left-handed, y up, rays through pixel centres.
struct Camera {
    Vec eye, forward, right, up;
    float tanHalf, aspect;
    int width, height;

    explicit Camera(const View& o)
        : eye(o.eye), forward(normalize(o.target - o.eye)), tanHalf(float(std::tan(o.fov * M_PI / 360))),
          aspect(float(o.width) / float(o.height)), width(o.width), height(o.height) {
        right = normalize(cross(Vec{0, 1, 0}, forward));
        up = cross(forward, right);
    }
    Vec dir(int px, int py) const {
        float u = (px + 0.5f) / float(width), v = (py + 0.5f) / float(height);
        return normalize(forward + ((2 * u - 1) * tanHalf * aspect) * right + ((1 - 2 * v) * tanHalf) * up);
    }
};

struct Counts {
    uint64_t camera = 0, shadow = 0;
};

/// One camera ray, and one shadow ray where the surface faces the light; returns the grey
/// level (ambient 0.1 + Lambert 0.9, white light, white material). The geometric normal is
/// turned toward the camera: crtc shades both sides of a surface.
inline float shadePixel(RTCScene scene, const Camera& cam, const Vec& light, int px, int py, Counts& counts) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    Vec d = cam.dir(px, py);
    RTCRayHit rh{};
    rh.ray.org_x = cam.eye.x, rh.ray.org_y = cam.eye.y, rh.ray.org_z = cam.eye.z;
    rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    ++counts.camera;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    Vec p = cam.eye + rh.ray.tfar * d;
    Vec n = normalize(Vec{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
    if (dot(n, d) > 0) n = -1.0f * n;
    Vec toLight = light - p;
    float nDotL = dot(n, normalize(toLight));
    float grey = 0.1f;
    if (nDotL <= 0) return grey;
    // Off the surface by a small multiple of the hit distance, as any float tracer must.
    Vec origin = p + (1e-4f * rh.ray.tfar) * n;
    RTCRay shadow{};
    shadow.org_x = origin.x, shadow.org_y = origin.y, shadow.org_z = origin.z;
    Vec toLightFromOrigin = light - origin;
    shadow.dir_x = toLightFromOrigin.x, shadow.dir_y = toLightFromOrigin.y, shadow.dir_z = toLightFromOrigin.z;
    shadow.tnear = 0;
    shadow.tfar = 1;
    shadow.mask = ~0u;
    rtcOccluded1(scene, &context, &shadow);
    ++counts.shadow;
    if (shadow.tfar >= 0) grey += 0.9f * nDotL; // tfar becomes -inf when occluded
    return grey;
}

inline double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

inline void writePpm(const std::string& path, const std::vector<float>& grey, int width, int height) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        std::perror(path.c_str());
        std::exit(1);
    }
    std::fprintf(f, "P5\n%d %d\n255\n", width, height);
    for (float g : grey) std::fputc(int(std::fmin(g, 1.0f) * 255 + 0.5f), f);
    std::fclose(f);
}

/// Builds the scene `attach` fills (its geometry attached, not committed), times its commit
/// and the render of the view, and prints the report after `what` ("spheres 10000").
inline int run(const View& o, const std::string& what,
               const std::function<void(RTCDevice, RTCScene)>& attach) {
    // Embree's own worker threads (for the build) limited to the render's count.
    const std::string config = "threads=" + std::to_string(o.threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) {
        std::fprintf(stderr, "embree: rtcNewDevice failed (error %d)\n", int(rtcGetDeviceError(nullptr)));
        return 1;
    }
    RTCScene scene = rtcNewScene(device);
    attach(device, scene);
    auto t0 = std::chrono::steady_clock::now();
    rtcCommitScene(scene);
    auto t1 = std::chrono::steady_clock::now();
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) {
        std::fprintf(stderr, "embree: building the scene failed\n");
        return 1;
    }

    const Camera camera(o);
    std::vector<float> image(size_t(o.width) * size_t(o.height));
    std::vector<Counts> counts(size_t(o.threads));
    std::atomic<int> nextRow{0};
    auto worker = [&](int id) {
        for (int y; (y = nextRow.fetch_add(1)) < o.height;)
            for (int x = 0; x < o.width; ++x)
                image[size_t(y) * size_t(o.width) + size_t(x)] = shadePixel(scene, camera, o.light, x, y, counts[size_t(id)]);
    };
    auto t2 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int id = 1; id < o.threads; ++id) pool.emplace_back(worker, id);
    worker(0);
    for (std::thread& t : pool) t.join();
    auto t3 = std::chrono::steady_clock::now();

    Counts total;
    for (const Counts& c : counts) total.camera += c.camera, total.shadow += c.shadow;
    const uint64_t rays = total.camera + total.shadow;
    const double render = seconds(t2, t3);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("%s\n", what.c_str());
    std::printf("rays camera %llu shadow %llu total %llu\n", (unsigned long long)total.camera,
                (unsigned long long)total.shadow, (unsigned long long)rays);
    std::printf("build %.4f\nrender %.4f\nmrays %.3f\npeak_kb %ld\n", seconds(t0, t1), render,
                double(rays) / render / 1e6, usage.ru_maxrss);
    if (!o.ppm.empty()) writePpm(o.ppm, image, o.width, o.height);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}

} // namespace harness
