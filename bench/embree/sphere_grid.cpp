// The Embree side of bench/embree/run.sh (see bench/README.md, "Ray kernel vs Embree 3"): a
// grid of spheres (RTC_GEOMETRY_TYPE_SPHERE_POINT), a pinhole camera with crtc's conventions
// and a point light; per pixel one camera ray (rtcIntersect1) and, where the surface faces
// the light, one shadow ray (rtcOccluded1), shaded with ambient + Lambert as crtc's plain
// diffuse material is. Every number describing the scene comes from the command line, so the
// script that writes the CRT scene is the only place they are set.
//
// Prints rays by kind, BVH build and render seconds, the render rate and the peak resident
// memory, one "key value" per line. Built by run.sh only; crtc does not depend on it.
#include <embree3/rtcore.h>

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Vec {
    float x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(float s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec normalize(Vec a) { return (1.0f / std::sqrt(dot(a, a))) * a; }

struct Options {
    int grid = 100;         ///< spheres per side: grid² spheres
    double spacing = 1.0;   ///< between neighbouring centres
    double radius = 0.45;
    int width = 800, height = 600, threads = 1;
    Vec eye{0, 50, -30}, target{0, 0, 50}, light{-30, 80, -20};
    double fov = 40;        ///< vertical, degrees
    std::string ppm;        ///< optional image, to compare with crtc's by eye
};

/// crtc's pinhole camera (tracer/camera.cpp): left-handed, y up, rays through pixel centres.
struct Camera {
    Vec eye, forward, right, up;
    float tanHalf, aspect;
    int width, height;

    explicit Camera(const Options& o)
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
/// level (ambient 0.1 + Lambert 0.9, white light, white material).
float shadePixel(RTCScene scene, const Camera& cam, const Vec& light, int px, int py, Counts& counts) {
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

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

RTCScene buildScene(RTCDevice device, const Options& o) {
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    const size_t count = size_t(o.grid) * size_t(o.grid);
    auto* points = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), count));
    // Centres as run.sh writes them in CRT: x = spacing·(i − (grid−1)/2), y = radius, z = spacing·j.
    for (int i = 0; i < o.grid; ++i)
        for (int j = 0; j < o.grid; ++j) {
            float* p = points + 4 * (size_t(i) * size_t(o.grid) + size_t(j));
            p[0] = float(o.spacing * (i - (o.grid - 1) / 2.0));
            p[1] = float(o.radius);
            p[2] = float(o.spacing * j);
            p[3] = float(o.radius);
        }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    return scene;
}

void writePpm(const std::string& path, const std::vector<float>& grey, int width, int height) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        std::perror(path.c_str());
        std::exit(1);
    }
    std::fprintf(f, "P5\n%d %d\n255\n", width, height);
    for (float g : grey) std::fputc(int(std::fmin(g, 1.0f) * 255 + 0.5f), f);
    std::fclose(f);
}

[[noreturn]] void usage(const char* self) {
    std::fprintf(stderr,
                 "usage: %s --grid N --spacing S --radius R --size WxH --threads T\n"
                 "          --eye X,Y,Z --target X,Y,Z --fov DEG --light X,Y,Z [--ppm FILE]\n",
                 self);
    std::exit(2);
}

Vec parseVec(const char* self, const char* text) {
    Vec v;
    if (std::sscanf(text, "%f,%f,%f", &v.x, &v.y, &v.z) != 3) usage(self);
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        if (i + 1 >= argc) usage(argv[0]);
        const char* value = argv[++i];
        if (!std::strcmp(arg, "--grid")) o.grid = std::atoi(value);
        else if (!std::strcmp(arg, "--spacing")) o.spacing = std::atof(value);
        else if (!std::strcmp(arg, "--radius")) o.radius = std::atof(value);
        else if (!std::strcmp(arg, "--size")) {
            if (std::sscanf(value, "%dx%d", &o.width, &o.height) != 2) usage(argv[0]);
        } else if (!std::strcmp(arg, "--threads")) o.threads = std::atoi(value);
        else if (!std::strcmp(arg, "--eye")) o.eye = parseVec(argv[0], value);
        else if (!std::strcmp(arg, "--target")) o.target = parseVec(argv[0], value);
        else if (!std::strcmp(arg, "--light")) o.light = parseVec(argv[0], value);
        else if (!std::strcmp(arg, "--fov")) o.fov = std::atof(value);
        else if (!std::strcmp(arg, "--ppm")) o.ppm = value;
        else usage(argv[0]);
    }
    // Bounded like crtc's own limits, so a typo cannot ask for terabytes.
    if (o.grid < 1 || o.grid > 10000 || o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384 ||
        o.threads < 1 || o.threads > 256 || !(o.radius > 0))
        usage(argv[0]);
    return o;
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    // Embree's own worker threads (for the build) limited to the render's count.
    const std::string config = "threads=" + std::to_string(o.threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) {
        std::fprintf(stderr, "embree: rtcNewDevice failed (error %d)\n", int(rtcGetDeviceError(nullptr)));
        return 1;
    }
    RTCScene scene = buildScene(device, o);
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
    std::printf("spheres %zu\n", size_t(o.grid) * size_t(o.grid));
    std::printf("rays camera %llu shadow %llu total %llu\n", (unsigned long long)total.camera,
                (unsigned long long)total.shadow, (unsigned long long)rays);
    std::printf("build %.4f\nrender %.4f\nmrays %.3f\npeak_kb %ld\n", seconds(t0, t1), render,
                double(rays) / render / 1e6, usage.ru_maxrss);
    if (!o.ppm.empty()) writePpm(o.ppm, image, o.width, o.height);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
