// Analytic render tests of the separate reflection and refraction depths (Settings
// reflectiondepth and refractiondepth beside recursiondepth): two facing mirrors show as many
// reflections as reflectiondepth allows, a stack of transparent sheets as many crossings as
// refractiondepth allows, and neither limit touches the other kind of bounce.
//
// Every surface is emissive with no lights, so a pixel is a geometric series of the emissions
// along the path, cut where the limit stops it.
#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

#include <cmath>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

constexpr int kSize = 8;
constexpr double kEmission = 0.1;
constexpr double kBounce = 0.5; ///< reflectivity of the mirrors, transparency of the sheets
constexpr double kBackground = 0.8;
constexpr int kSheets = 4;

/// The camera between two parallel mirrors z = 0 and z = -10, looking at the first; behind
/// the camera's side, past the mirrors, nothing. Beside them, in front of the camera but off
/// to the right, nothing either: every pixel sees the mirrors.
scene::SceneDesc mirrors() {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 0, -5}, {0, 0, 0}, 20));
    ShadingMaterial mirror;
    mirror.color = scene::Color{0, 0, 0, 1};
    mirror.diffuse = 0;
    mirror.reflectivity = kBounce;
    mirror.emission = scene::Color{kEmission, kEmission, kEmission, 1};
    int32_t material = m.material(mirror);
    m.draw(m.plane({0, 0, -1}, {0, 0, 0}, material));
    m.draw(m.plane({0, 0, 1}, {0, 0, -10}, material));
    return m.desc;
}

/// The camera looking through kSheets transparent emissive sheets (thin, so unbent) at a
/// grey background.
scene::SceneDesc sheets() {
    SceneMaker m;
    m.desc = blankScene(kSize, kSize, lookAt({0, 0, -5}, {0, 0, 0}, 20));
    m.desc.background.color = scene::Color{kBackground, kBackground, kBackground, 1};
    ShadingMaterial sheet;
    sheet.color = scene::Color{1, 1, 1, 1};
    sheet.diffuse = 0;
    sheet.transparency = kBounce;
    sheet.emission = scene::Color{kEmission, kEmission, kEmission, 1};
    int32_t material = m.material(sheet);
    for (int i = 0; i < kSheets; ++i) {
        double z = i;
        m.draw(
            m.entity(scene::QuadShape{{-100, -100, z}, {200, 0, 0}, {0, 200, 0}}, material, false));
    }
    return m.desc;
}

/// The emission of the first `seen` surfaces, each seen through kBounce of the one before.
double series(int seen) {
    double sum = 0, weight = 1;
    for (int i = 0; i < seen; ++i, weight *= kBounce) sum += kEmission * weight;
    return sum;
}

/// Mirrors: with k reflections allowed, the first surface and k reflections of it.
double mirrorsExpected(int reflections) {
    return series(reflections + 1);
}

/// Sheets: with k refractions allowed, k + 1 sheets, and the background once all are passed.
double sheetsExpected(int refractions) {
    if (refractions < kSheets) return series(refractions + 1);
    return series(kSheets) + std::pow(kBounce, kSheets) * kBackground;
}

void checkEveryPixel(const scene::SceneDesc& desc, double want) {
    PixelBuffer image = renderOk(desc);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            INFO("pixel " << x << "," << y << " want " << want);
            CHECK(maxDifference(pixelAt(image, x, y), DVec3(want)) < 1e-6);
        }
}

struct Depths {
    int recursion;
    int reflection; ///< -1: not given
    int refraction; ///< -1: not given
};

scene::SceneDesc withDepths(scene::SceneDesc desc, Depths d) {
    desc.settings.recursionDepth = d.recursion;
    desc.settings.reflectionDepth = d.reflection;
    desc.settings.refractionDepth = d.refraction;
    return desc;
}

} // namespace

TEST_CASE("reflectiondepth sets how many reflections two facing mirrors show",
          "[render][analytic]") {
    // The series differ by at least 0.1·0.5^6 between consecutive depths: each case is exact.
    const struct {
        Depths depths;
        int reflections;
    } cases[] = {
        {{3, -1, -1}, 3},                  // recursiondepth alone sets both
        {{5, -1, -1}, 5}, {{3, 5, -1}, 5}, // an explicit reflectiondepth overrides it for
                                           // reflections
        {{3, 1, -1}, 1},  {{6, 2, -1}, 2}, {{3, 0, -1}, 0},
        {{3, -1, 0}, 3}, // the refraction limit does not touch reflections
        {{3, -1, 6}, 3}, // nor does a larger one let reflections go deeper
        {{3, 4, 0}, 4},
    };
    for (const auto& c : cases) {
        INFO("recursion " << c.depths.recursion << " reflection " << c.depths.reflection
                          << " refraction " << c.depths.refraction);
        checkEveryPixel(withDepths(mirrors(), c.depths), mirrorsExpected(c.reflections));
    }
}

TEST_CASE("refractiondepth sets how many transparent sheets a ray passes", "[render][analytic]") {
    const struct {
        Depths depths;
        int refractions;
    } cases[] = {
        {{3, -1, -1}, 3}, {{4, -1, -1}, 4}, // all four sheets, then the background
        {{3, -1, 4}, 4},                    // an explicit refractiondepth overrides recursiondepth
        {{3, -1, 1}, 1},  {{6, -1, 2}, 2},
        {{3, -1, 0}, 0},  {{3, 0, -1}, 3}, // the reflection limit does not touch refractions
        {{3, 6, -1}, 3},  {{3, 0, 5}, 5},
    };
    for (const auto& c : cases) {
        INFO("recursion " << c.depths.recursion << " reflection " << c.depths.reflection
                          << " refraction " << c.depths.refraction);
        checkEveryPixel(withDepths(sheets(), c.depths), sheetsExpected(c.refractions));
    }
}
