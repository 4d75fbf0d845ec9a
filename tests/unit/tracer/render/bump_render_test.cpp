// Render tests of bump textures: every kind and mapping tilts the shading normal on a sphere,
// a plane and a box, in the direction and by the amount its height field says.
//
// Image bumps read a small height image that the test writes itself (tracer/image_io) into a
// scratch folder. Without a working bump the bumped and plain renders are identical, so every
// test here fails then.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"
#include "../scratch_folder.hpp"
#include "tracer/image_io/image_io.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// This process's folder for height images, removed when it ends.
const std::filesystem::path& scratchFolder() {
    // Image bumps are read through the OpenImageIO module, built beside crtc.
    setenv("CRT_IMAGE_IO_MODULE", CRT_TEST_IMAGE_IO_MODULE, 0);
    return scratch();
}

/// Writes a grey 8-bit PNG whose texel (column x, row y from the top) is height(x, y) in
/// [0, 1]; returns its path. Heights are stored as raw codes (gamma 1), as bumps read them.
std::string writeHeightImage(const std::string& name, int width, int height,
                             const std::function<double(int, int)>& heightAt) {
    image_io::ImageBuffer image;
    image.width = width;
    image.height = height;
    image.pixels.resize(static_cast<size_t>(3 * width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                image.pixels[static_cast<size_t>(3 * (y * width + x) + c)] =
                    static_cast<float>(heightAt(x, y));
    std::string path = (scratchFolder() / name).string();
    std::string error;
    bool written = image_io::writeImage(path, image, image_io::WriteOptions{}, error);
    INFO(error);
    REQUIRE(written);
    return path;
}

/// Smooth bumps, four periods each way across the image.
std::string bumpsImage() {
    static const std::string path = writeHeightImage("bumps.png", 64, 64, [](int x, int y) {
        return 0.5 + 0.5 * std::sin(2 * kTestPi * 4 * (x + 0.5) / 64) *
                         std::sin(2 * kTestPi * 4 * (y + 0.5) / 64);
    });
    return path;
}

scene::TextureDesc noiseBump(double size, double strength) {
    scene::TextureDesc t;
    t.kind = scene::TextureKind::NoiseBump;
    t.size = size;
    t.strength = strength;
    return t;
}

scene::TextureDesc imageBump(const std::string& path, scene::TextureMapping mapping,
                             double strength, double size = 1) {
    scene::TextureDesc t;
    t.kind = scene::TextureKind::ImageBump;
    t.file = path;
    t.resolvedFile = path;
    t.mapping = mapping;
    t.strength = strength;
    t.size = size;
    return t;
}

/// A diffuse grey material, bumped by `bump` when given.
int32_t bumpedMaterial(SceneMaker& m, const std::optional<scene::TextureDesc>& bump) {
    ShadingMaterial mat;
    mat.color = scene::Color{0.8, 0.8, 0.8, 1};
    if (bump) {
        m.desc.textures.push_back(*bump);
        mat.bump = static_cast<int32_t>(m.desc.textures.size() - 1);
    }
    return m.material(mat);
}

enum class Shape { Sphere, Plane, Box };

/// One shape under an oblique parallel light, with a little ambient light so that every pixel
/// of the shape is brighter than the black background.
scene::SceneDesc litShape(Shape shape, const std::optional<scene::TextureDesc>& bump) {
    const int W = 64, H = 48;
    SceneMaker m;
    switch (shape) {
    case Shape::Sphere:
        m.desc = blankScene(W, H, lookAt({0, 0.8, -4}, {0, 0, 0}, 36));
        m.draw(m.sphere({0, 0, 0}, 1, bumpedMaterial(m, bump)));
        break;
    case Shape::Plane:
        // Tilted, so that every mapping's coordinates vary over it (a planar mapping
        // projects along z, and a level plane at a fixed height is edge-on to that).
        m.desc = blankScene(W, H, lookAt({0.3, 1, -3}, {0, 0, 1.5}, 50));
        m.draw(m.plane({0, 0.5, -1}, {0, 0, 1.5}, bumpedMaterial(m, bump)));
        break;
    case Shape::Box:
        // Three faces in view: top, front and right.
        m.desc = blankScene(W, H, lookAt({2.5, 2.2, -4}, {0, 0, 0}, 40));
        m.draw(m.box({-1, -1, -1}, {1, 1, 1}, bumpedMaterial(m, bump)));
        break;
    }
    m.desc.settings.ambient = scene::Color{0.1, 0.1, 0.1, 1};
    m.desc.lights.push_back(parallelLight({-2, 3, -3}));
    return m.desc;
}

const char* shapeName(Shape s) {
    switch (s) {
    case Shape::Sphere: return "sphere";
    case Shape::Plane: return "plane";
    case Shape::Box: return "box";
    }
    return "?";
}

/// How a bump changed a render, over the pixels where the plain render shows the shape.
struct Change {
    int shapePixels = 0;
    int changed = 0;       ///< pixels whose largest channel difference exceeds kChanged
    double meanChange = 0; ///< mean of that difference over the shape's pixels
};

constexpr double kChanged = 0.02; // five 8-bit steps: a visible change

Change compare(const PixelBuffer& plain, const PixelBuffer& bumped) {
    Change c;
    double sum = 0;
    for (int y = 0; y < plain.height; ++y) {
        for (int x = 0; x < plain.width; ++x) {
            DVec3 a = pixelAt(plain, x, y);
            if (a == DVec3(0.0)) continue; // background
            double d = maxDifference(a, pixelAt(bumped, x, y));
            ++c.shapePixels;
            sum += d;
            if (d > kChanged) ++c.changed;
        }
    }
    c.meanChange = c.shapePixels > 0 ? sum / c.shapePixels : 0;
    return c;
}

/// Requires the bump to change at least 40% of the shape's pixels visibly, and the shape's
/// pixels by 0.03 on average (a bump that does nothing changes none).
void requireVisibleBump(Shape shape, const scene::TextureDesc& bump, const std::string& what) {
    PixelBuffer plain = renderOk(litShape(shape, std::nullopt));
    PixelBuffer bumped = renderOk(litShape(shape, bump));
    Change c = compare(plain, bumped);
    INFO(what << " on a " << shapeName(shape) << ": " << c.changed << " of " << c.shapePixels
              << " pixels changed, mean change " << c.meanChange);
    REQUIRE(c.shapePixels > plain.width * plain.height / 5);
    CHECK(c.changed * 5 >= c.shapePixels * 2);
    CHECK(c.meanChange >= 0.03);
}

} // namespace

TEST_CASE("NoiseBump visibly perturbs the shading of a sphere, a plane and a box",
          "[render][bump]") {
    for (Shape shape : {Shape::Sphere, Shape::Plane, Shape::Box})
        requireVisibleBump(shape, noiseBump(0.2, 1), "NoiseBump");
}

TEST_CASE("ImageBump visibly perturbs the shading in every mapping, on a sphere, a plane and a box",
          "[render][bump]") {
    const std::pair<scene::TextureMapping, const char*> mappings[] = {
        {scene::TextureMapping::Uv, "uv"},
        {scene::TextureMapping::Planar, "planar"},
        {scene::TextureMapping::Spherical, "spherical"},
        {scene::TextureMapping::Cylindrical, "cylindrical"},
        {scene::TextureMapping::Cubic, "cubic"},
    };
    for (const auto& [mapping, name] : mappings)
        for (Shape shape : {Shape::Sphere, Shape::Plane, Shape::Box})
            requireVisibleBump(shape, imageBump(bumpsImage(), mapping, 2),
                               std::string("ImageBump ") + name);
}

TEST_CASE("A uv height ramp tilts the normal towards -u by strength x 0.1 x the slope",
          "[render][bump]") {
    // A box's top face (+y) has u along +z (axis (1 + 1) mod 3) over its whole width of 2. The
    // image rises by 1/15 per texel over 16 texels: 16/15 per unit of u, so the height rises
    // by 8/15 per unit of z and the normal tilts to normalize(0, 1, −0.1 · strength · 8/15).
    // Lit from −z, the face gets brighter; lit from +z, darker.
    const int W = 48, H = 48;
    const double strength = 10, slope = 8.0 / 15;
    std::string ramp = writeHeightImage("ramp.png", 16, 4, [](int x, int) { return x / 15.0; });
    const DVec3 bumped = glm::normalize(DVec3(0, 1, -0.1 * strength * slope));
    scene::CameraDesc camera = lookAt({0, 6, 0}, {0, 1, 0}, 30);
    camera.up = {0, 0, 1};
    for (double side : {-1.0, 1.0}) {
        const DVec3 toLight = glm::normalize(DVec3(0, 1, side));
        auto render = [&](bool withBump) {
            SceneMaker m;
            m.desc = blankScene(W, H, camera);
            std::optional<scene::TextureDesc> bump;
            if (withBump) bump = imageBump(ramp, scene::TextureMapping::Uv, strength);
            m.draw(m.box({-1, -1, -1}, {1, 1, 1}, bumpedMaterial(m, bump)));
            m.desc.lights.push_back(parallelLight(toLight));
            return renderOk(m.desc);
        };
        PixelBuffer plain = render(false), tilted = render(true);
        const double wantPlain = 0.8 * glm::dot(DVec3(0, 1, 0), toLight);
        const double wantBumped = 0.8 * glm::dot(bumped, toLight);
        int checked = 0;
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                auto t = hitPlane(specCameraRay(camera, W, H, x, y), {0, 1, 0}, {0, 1, 0});
                if (!t) continue;
                DVec3 p = specCameraRay(camera, W, H, x, y).at(*t);
                // Inside the face, away from its edges and from the image's wrap-around
                // (the last texel blends into the first within half a texel of u = 0 and 1).
                if (std::abs(p.x) > 0.95 || std::abs(p.z) > 0.9) continue;
                INFO("pixel " << x << "," << y << " at z = " << p.z << ", light side " << side);
                double before = pixelAt(plain, x, y).x, after = pixelAt(tilted, x, y).x;
                CHECK(std::abs(before - wantPlain) < 1e-4);
                CHECK(std::abs(after - wantBumped) < 1e-4);
                // Lit from −z the face turns towards the light (0.57 → 0.77), from +z away
                // from it (0.57 → 0.23).
                CHECK((side < 0 ? after > before + 0.1 : after < before - 0.3));
                ++checked;
            }
        }
        CHECK(checked > W * H / 4);
    }
}

namespace {

/// The bumps image with its columns moved: column j of the new image is column
/// source(j) of bumpsImage(), so that another mapping reads the same heights as "uv" does.
std::string bumpsImageWithColumns(const std::string& name, const std::function<int(int)>& source) {
    return writeHeightImage(name, 64, 64, [&](int x, int y) {
        int s = source(x);
        return 0.5 + 0.5 * std::sin(2 * kTestPi * 4 * (s + 0.5) / 64) *
                         std::sin(2 * kTestPi * 4 * (y + 0.5) / 64);
    });
}

/// Renders `shape` (drawn with one material) under an oblique light, with the given bump.
PixelBuffer renderShape(const scene::CameraDesc& camera, const scene::Shape& shape,
                        const std::optional<scene::TextureDesc>& bump) {
    SceneMaker m;
    m.desc = blankScene(64, 48, camera);
    m.desc.settings.ambient = scene::Color{0.1, 0.1, 0.1, 1};
    m.draw(m.entity(shape, bumpedMaterial(m, bump)));
    m.desc.lights.push_back(parallelLight({-1, 1.5, -2}));
    return renderOk(m.desc);
}

/// Requires two bumps of the same heights through different mappings to shade the shape the
/// same: within 2e-3 on 97% of its pixels (finite differences of a bilinear image differ
/// where a step crosses a texel's centre line), while they change it visibly.
void requireSameBump(const scene::CameraDesc& camera, const scene::Shape& shape,
                     const scene::TextureDesc& uvBump, const scene::TextureDesc& otherBump) {
    PixelBuffer plain = renderShape(camera, shape, std::nullopt);
    PixelBuffer viaUv = renderShape(camera, shape, uvBump);
    PixelBuffer viaOther = renderShape(camera, shape, otherBump);
    Change change = compare(plain, viaUv);
    Change difference = compare(viaOther, viaUv);
    int close = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x)
            if (pixelAt(plain, x, y) != DVec3(0.0) &&
                maxDifference(pixelAt(viaUv, x, y), pixelAt(viaOther, x, y)) < 2e-3)
                ++close;
    INFO("bump changed " << change.changed << " of " << change.shapePixels
                         << " pixels; the mappings agree on " << close << ", mean difference "
                         << difference.meanChange);
    REQUIRE(change.shapePixels > 400);
    CHECK(change.changed * 3 >= change.shapePixels);
    CHECK(close >= 0.97 * change.shapePixels);
}

} // namespace

TEST_CASE("A uv bump on a box face equals the planar bump that maps the same image the same way",
          "[render][bump]") {
    // The front face (z = 0) of the box (0,0,0)–(2,2,2): uv = (x/2, y/2), read at image
    // (x/2, 1 − y/2); planar with size 2 reads (fract(x/2), fract(−y/2)): the same texels.
    scene::BoxShape box{{0, 0, 0}, {2, 2, 2}};
    requireSameBump(lookAt({1, 1, -5}, {1, 1, 0}, 30), box,
                    imageBump(bumpsImage(), scene::TextureMapping::Uv, 2),
                    imageBump(bumpsImage(), scene::TextureMapping::Planar, 2, 2));
}

TEST_CASE("A uv bump on a sphere equals the spherical bump of the mirrored image",
          "[render][bump]") {
    // uv: u = atan2(z, x) / 2π; spherical: 0.5 + atan2(x, z) / 2π = 0.75 − u (mod 1); both
    // read the row 0.5 − asin(y) / π. Mirroring the columns about u = 0.375 makes them agree.
    std::string mirrored = bumpsImageWithColumns(
        "bumps_mirrored.png", [](int j) { return ((48 - 1 - j) % 64 + 64) % 64; });
    scene::SphereShape sphere{{0, 0, 0}, 1};
    requireSameBump(lookAt({0, 0.8, -4}, {0, 0, 0}, 36), sphere,
                    imageBump(bumpsImage(), scene::TextureMapping::Uv, 2),
                    imageBump(mirrored, scene::TextureMapping::Spherical, 2));
}

TEST_CASE("A uv bump on a cylinder's side equals the cylindrical bump of the turned image",
          "[render][bump]") {
    // A cylinder along +y: uv u = atan2(−z, x) / 2π (its frame's u axis is +x, v is −z),
    // v = y / height; cylindrical reads 0.5 + atan2(x, z) / 2π = u + 0.75 (mod 1) and
    // fract(−y / size) = 1 − y/2 with size 2. Turning the columns by 48 makes them agree.
    std::string turned =
        bumpsImageWithColumns("bumps_turned.png", [](int j) { return ((j - 48) % 64 + 64) % 64; });
    scene::CylinderShape cylinder{{0, 0, 0}, {0, 2, 0}, 1, false};
    requireSameBump(lookAt({0, 1, -5}, {0, 1, 0}, 36), cylinder,
                    imageBump(bumpsImage(), scene::TextureMapping::Uv, 2),
                    imageBump(turned, scene::TextureMapping::Cylindrical, 2, 2));
}

TEST_CASE("A uv ImageBump visibly perturbs every other primitive with uv", "[render][bump]") {
    // A mesh: one quad in two triangles whose vt span two tiles of the image each way.
    std::string obj = (scratchFolder() / "quad.obj").string();
    {
        std::ofstream out(obj);
        out << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
               "vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"
               "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    }
    const std::pair<scene::Shape, const char*> shapes[] = {
        {scene::CylinderShape{{0, -1, 0}, {0, 1, 0}, 0.8, false}, "cylinder"},
        {scene::ConeShape{{0, -1, 0}, 1, {0, 1, 0}, 0.2, false}, "cone"},
        {scene::TorusShape{{0, 0, 0}, 0.9, 0.4, {0, 1, 0}}, "torus"},
        {scene::DiscShape{{0, 0, 0}, {0, 0.3, -1}, 1.2, 0.2}, "disc"},
        {scene::QuadShape{{-1, -1, 0}, {2, 0, 0}, {0.3, 2, 0}}, "quad"},
        {scene::TriangleShape{{-1.2, -1, 0}, {1.2, -1, 0}, {0, 1.2, 0}}, "triangle"},
        {scene::MeshShape{obj, obj}, "mesh"},
    };
    const scene::CameraDesc camera = lookAt({0.5, 1.5, -4}, {0, 0, 0}, 40);
    for (const auto& [shape, name] : shapes) {
        PixelBuffer plain = renderShape(camera, shape, std::nullopt);
        PixelBuffer bumped =
            renderShape(camera, shape, imageBump(bumpsImage(), scene::TextureMapping::Uv, 2));
        Change c = compare(plain, bumped);
        INFO(name << ": " << c.changed << " of " << c.shapePixels << " pixels changed, mean change "
                  << c.meanChange);
        REQUIRE(c.shapePixels > 300);
        CHECK(c.changed * 5 >= c.shapePixels * 2);
        CHECK(c.meanChange >= 0.03);
    }
}

TEST_CASE("A uv bump turns with its object", "[render][bump]") {
    // The box turned 90° about y, seen with the camera and light turned the same way, shows
    // the same image as the box as it is: the bump's tangents are carried into world space.
    // (Turning (x, y, z) by 90° about y gives (z, y, −x) in the spec's left-handed convention.)
    auto turn = [](DVec3 v) { return DVec3(v.z, v.y, -v.x); };
    const DVec3 eye(2.5, 2.2, -4), toLight(-2, 3, -3);
    auto render = [&](bool turned, bool bumped) {
        SceneMaker m;
        scene::CameraDesc camera =
            turned ? lookAt(turn(eye), {0, 0, 0}, 40) : lookAt(eye, {0, 0, 0}, 40);
        m.desc = blankScene(64, 48, camera);
        std::optional<scene::TextureDesc> bump;
        if (bumped) bump = imageBump(bumpsImage(), scene::TextureMapping::Uv, 2);
        int32_t box = m.box({-1, -1, -1}, {1, 1, 1}, bumpedMaterial(m, bump));
        m.draw(turned ? m.transformed(box, {rotate({0, 90, 0})}) : box);
        m.desc.lights.push_back(parallelLight(turned ? turn(toLight) : toLight));
        return renderOk(m.desc);
    };
    PixelBuffer straight = render(false, true), turned = render(true, true);
    Change change = compare(render(false, false), straight);
    INFO("the bump changed " << change.changed << " of " << change.shapePixels << " pixels");
    CHECK(change.changed * 2 >= change.shapePixels);
    int shapePixels = 0, same = 0;
    for (int y = 0; y < straight.height; ++y)
        for (int x = 0; x < straight.width; ++x) {
            if (pixelAt(straight, x, y) == DVec3(0.0)) continue;
            ++shapePixels;
            if (maxDifference(pixelAt(straight, x, y), pixelAt(turned, x, y)) < 1e-3) ++same;
        }
    INFO(same << " of " << shapePixels << " pixels agree");
    REQUIRE(shapePixels > 400);
    CHECK(same >= 0.99 * shapePixels);
}
