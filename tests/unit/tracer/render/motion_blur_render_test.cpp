// Motion blur: a glowing sphere moved across the shutter, seen by an orthographic camera (whose
// pixels map to the scene linearly), leaves a streak as long as its path plus its diameter,
// each point of it lit for the share of the shutter the sphere covers it.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include "tracer/motion.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

// 160 × 24 pixels over 8 × 1.2 units: 20 pixels a unit, x = 0 between columns 79 and 80.
constexpr int kWidth = 160, kHeight = 24;
constexpr double kViewWidth = 8, kPixelsPerUnit = kWidth / kViewWidth;
constexpr double kRadius = 0.5, kFrom = -2, kTo = 2;
constexpr int kRow = kHeight / 2; // its centre 0.025 above the path

scene::CameraDesc orthographicCamera(double x = 0) {
    scene::CameraDesc c = lookAt({x, 0, -10}, {x, 0, 0}, 60);
    c.projection = scene::Projection::Orthographic;
    c.width = kViewWidth;
    return c;
}

/// A material that only glows, white: a pixel is the share of its samples that meet it.
int32_t glowing(SceneMaker& m) {
    ShadingMaterial glow;
    glow.color = scene::Color{0, 0, 0, 1};
    glow.diffuse = 0;
    glow.emission = scene::Color{1, 1, 1, 1};
    return m.material(glow);
}

/// A glowing sphere (kRadius at the origin) drawn moved by `modifiers`, which the motion
/// steps replace when given.
enum class Built { Alone, InCsg, InCrowd };

scene::SceneDesc glowingScene(const std::vector<scene::Modifier>& modifiers,
                              const std::vector<std::vector<scene::Modifier>>& steps = {}, Built built = Built::Alone) {
    SceneMaker m;
    m.desc = blankScene(kWidth, kHeight, orthographicCamera());
    m.desc.settings.supersampling = 8;
    m.desc.settings.antialias = scene::Antialias::Stratified;
    const int32_t material = glowing(m);
    int32_t shape = m.sphere({0, 0, 0}, kRadius, material);
    // The same sphere as a CSG tree: the ball cut by a box that holds all of it.
    if (built == Built::InCsg) shape = m.csg(scene::CsgOp::Intersection, shape, m.box({-1, -1, -1}, {1, 1, 1}, material));
    // Or among many out of view, which move together as one instance.
    if (built == Built::InCrowd) {
        scene::GroupNode crowd{{shape}};
        for (int i = 0; i < 20; ++i) crowd.members.push_back(m.sphere({i, 100, 0}, 0.1, material));
        shape = m.entity(crowd);
    }
    const int32_t moved = m.transformed(shape, modifiers);
    m.draw(moved);
    if (!steps.empty()) m.desc.motion.transforms.emplace(moved, steps);
    return m.desc;
}

std::vector<std::vector<scene::Modifier>> sliding() {
    return {{translate({kFrom, 0, 0})}, {translate({kTo, 0, 0})}};
}

double columnX(int column) { return (column + 0.5) / kPixelsPerUnit - kViewWidth / 2; }

constexpr double kLit = 0.02; ///< a pixel brighter than this is part of the streak

/// The lit columns of the middle row: the first and the one past the last.
std::pair<int, int> litColumns(const PixelBuffer& image) {
    int first = -1, last = -1;
    for (int x = 0; x < kWidth; ++x)
        if (pixelAt(image, x, kRow).x > kLit) {
            if (first < 0) first = x;
            last = x;
        }
    return {first, last + 1};
}

/// Checks the streak along the middle row: a point at x is lit for the share of the shutter
/// the sphere's chord at the row's height (half-width c) covers it, |[x − c, x + c] ∩ [kFrom,
/// kTo]| / (kTo − kFrom); so it is lit brighter than kLit over kTo − kFrom + 2c less kLit's
/// share of the path at each end.
void checkStreak(const PixelBuffer& image) {
    const double y = 0.5 * kViewWidth / kWidth; // the row's centre: half a pixel above the path
    const double c = std::sqrt(kRadius * kRadius - y * y), path = kTo - kFrom;
    const auto [first, end] = litColumns(image);
    const double length = (end - first) / kPixelsPerUnit;
    INFO("lit from column " << first << " to " << end);
    CHECK(std::abs(length - (path + 2 * c - 2 * kLit * path)) <= 2 / kPixelsPerUnit);
    CHECK(std::abs(columnX(first) - (kFrom - c + kLit * path)) <= 1.5 / kPixelsPerUnit);
    double sum = 0, want = 0;
    for (int x = 0; x < kWidth; ++x) {
        const double at = columnX(x);
        const double share = std::max(0.0, std::min(at + c, kTo) - std::max(at - c, kFrom)) / path;
        INFO("column " << x << " at " << at);
        CHECK(std::abs(pixelAt(image, x, kRow).x - share) < 0.05);
        sum += pixelAt(image, x, kRow).x;
        want += share;
    }
    CHECK(std::abs(sum - want) < 0.01 * want);
}

} // namespace

TEST_CASE("a sphere moved across the shutter leaves a streak as long as its path", "[motion]") {
    SECTION("whitted") { checkStreak(renderOk(glowingScene({translate({0, 0, 0})}, sliding()))); }
    SECTION("path") {
        scene::SceneDesc desc = glowingScene({translate({0, 0, 0})}, sliding());
        desc.settings.integrator = scene::Integrator::Path;
        desc.settings.samples = 64;
        checkStreak(renderOk(desc));
    }
    SECTION("in a CSG tree") { checkStreak(renderOk(glowingScene({translate({0, 0, 0})}, sliding(), Built::InCsg))); }
    SECTION("among many that move with it") {
        checkStreak(renderOk(glowingScene({translate({0, 0, 0})}, sliding(), Built::InCrowd)));
    }
    SECTION("with the camera moving instead") {
        scene::SceneDesc desc = glowingScene({translate({0, 0, 0})});
        desc.motion.cameras = {orthographicCamera(-kFrom), orthographicCamera(-kTo)};
        checkStreak(renderOk(desc));
    }
    SECTION("without motion it stays a disc") {
        const auto [first, end] = litColumns(renderOk(glowingScene({translate({0, 0, 0})})));
        CHECK(std::abs((end - first) / kPixelsPerUnit - 2 * kRadius) <= 2 / kPixelsPerUnit);
    }
}

TEST_CASE("a moving scene renders the same bits on one thread and on two", "[motion]") {
    const scene::SceneDesc desc = glowingScene({translate({0, 0, 0})}, sliding());
    const PixelBuffer one = renderOk(desc, 1), two = renderOk(desc, 2);
    CHECK(one.pixels == two.pixels);
}

TEST_CASE("modifiers go linearly between steps, a turn by its angle", "[motion]") {
    const std::vector<std::vector<scene::Modifier>> steps = {
        {rotate({0, 0, 0}), translate({0, 0, 0})},
        {rotate({0, 0, 360}), translate({4, 0, 0})},
        {rotate({0, 0, 720}), translate({4, 2, 0})},
    };
    const std::vector<scene::Modifier> quarter = modifiersAt(steps, 0.25);
    CHECK(quarter[0].value.z == 180);
    CHECK(quarter[1].value == glm::dvec3(2, 0, 0));
    CHECK(modifiersAt(steps, 0.75)[1].value == glm::dvec3(4, 1, 0));
    CHECK(modifiersAt(steps, 1.0)[0].value.z == 720);
    // A half turn of a point at x = 1 about z, at a quarter of the shutter.
    const MovingTransform moving{Transform(), std::make_shared<const decltype(steps)>(steps)};
    const glm::dvec3 p = moving.at(0.25).toWorld.point({1, 0, 0});
    CHECK(std::abs(p.x - 1) < 1e-12); // rotated by 180° then moved by 2
    CHECK(std::abs(p.y) < 1e-12);
}

TEST_CASE("a cube turning a whole turn draws a ring", "[motion]") {
    // With two steps, 0° and 360°: a matrix interpolation would leave it where it was.
    SceneMaker m;
    m.desc = blankScene(64, 64, orthographicCamera());
    m.desc.camera.width = 3;
    m.desc.settings.supersampling = 8;
    m.desc.settings.antialias = scene::Antialias::Stratified;
    const int32_t cube = m.box({0.9, -0.1, -0.1}, {1.1, 0.1, 0.1}, glowing(m));
    const int32_t turned = m.transformed(cube, {rotate({0, 0, 0})});
    m.draw(turned);
    m.desc.motion.transforms.emplace(turned, std::vector<std::vector<scene::Modifier>>{{rotate({0, 0, 0})},
                                                                                       {rotate({0, 0, 360})}});
    const PixelBuffer image = renderOk(m.desc);
    // 64 pixels over 3 units: the ring of radius 1 passes 21.3 pixels from the centre (32, 32).
    for (auto [x, y] : {std::pair{53, 32}, std::pair{32, 10}, std::pair{10, 32}, std::pair{32, 53}}) {
        INFO(x << "," << y);
        CHECK(pixelAt(image, x, y).x > 0.03);
    }
    CHECK(pixelAt(image, 32, 32).x == 0);
}
