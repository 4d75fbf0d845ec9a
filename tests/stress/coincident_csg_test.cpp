// CSG operands with coincident faces render as the same solid built without coincidences.
//
// The expectation: a difference, intersection or union whose operands share face planes (a box
// minus a box sharing a face, a pocket flush with the top, a union of two boxes sharing a face)
// shows exactly the surfaces of the same solid built with the tool enlarged past every shared
// plane (what users do to dodge coincident faces), with the same materials: the operands'
// crossings on a shared plane are one event (docs/rendering.md, "Coincident faces"), so which
// face wins is never decided by rounding and there is no speckle. Because the visible surfaces
// and materials are identical, the 8-bit images may differ by more than 1/255 only where a
// pixel's ray passes within rounding of an edge: at most 0.1% of pixels (12 of 12,288).
// Speckle on a shared face would flip hundreds of pixels scattered over the whole face.
#include "stress_util.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;
using test::SceneMaker;

namespace {

constexpr int kWidth = 128, kHeight = 96;
constexpr double kAllowedPixels = 0.001 * kWidth * kHeight;

/// The operand box [-1, 1] × [0.3, 2.3] × [-1, 1], floating above the floor.
const DVec3 kLo(-1, 0.3, -1), kHi(1, 2.3, 1);

struct Materials {
    int32_t a, b;
};

/// A floor, lights and a camera; `solid` adds the CSG object and returns its root.
template <typename Solid> scene::SceneDesc stage(const Solid& solid) {
    SceneMaker m;
    m.desc = test::blankScene(kWidth, kHeight,
                              test::lookAt(DVec3(2.6, 4.1, -5.2), DVec3(0, 1.1, 0), 45));
    m.desc.background.color = scene::Color{0.2, 0.25, 0.3, 1};
    ShadingMaterial floor;
    floor.color = scene::Color{0.6, 0.6, 0.55, 1};
    floor.reflectivity = 0.2;
    floor.diffuse = 0.8;
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(floor)));
    ShadingMaterial a, b;
    a.color = scene::Color{0.8, 0.3, 0.2, 1};
    a.specular = 0.3;
    a.shininess = 15;
    b.color = scene::Color{0.2, 0.4, 0.8, 1};
    b.reflectivity = 0.3;
    b.diffuse = 0.7;
    m.draw(solid(m, Materials{m.material(a), m.material(b)}));
    scene::LightDesc point;
    point.kind = scene::LightKind::Point;
    point.origin = DVec3(-3, 6, -4);
    point.color = scene::Color{0.7, 0.7, 0.7, 1};
    m.desc.lights.push_back(point);
    m.desc.lights.push_back(parallelLight(glm::normalize(DVec3(1, 3, -2)), {0.35, 0.35, 0.35, 1}));
    return m.desc;
}

template <typename Coincident, typename Reference>
void checkSame(const char* name, const Coincident& coincident, const Reference& reference) {
    PixelBuffer got = test::renderOk(stage(coincident));
    PixelBuffer want = test::renderOk(stage(reference));
    ImageDiff diff = compare8bit(got, want);
    INFO(name << ": " << diff.over << " pixels differ from the solid without coincident faces "
              << "by more than 1/255 (allowed " << kAllowedPixels << "), largest difference "
              << diff.worst << "/255; pixels over: " << diff.where);
    CHECK(diff.over <= kAllowedPixels);
    WARN(name << ": largest difference " << diff.worst << "/255, " << diff.over
              << " pixels over 1/255 (allowed " << kAllowedPixels << ") " << diff.where);
}

int32_t differenceOf(SceneMaker& m, Materials mat, DVec3 lo, DVec3 hi) {
    return m.csg(scene::CsgOp::Difference, m.box(kLo, kHi, mat.a), m.box(lo, hi, mat.b));
}

} // namespace

TEST_CASE("A box minus a box sharing five face planes with it", "[stress][csg]") {
    // The right half removed: the tool shares the x = 1, top, bottom, front and back planes.
    checkSame(
        "half removed",
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {0, 0.3, -1}, kHi);
        },
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {0, -0.7, -2}, {2, 3.3, 2});
        });
}

TEST_CASE("A pocket flush with a box's top face", "[stress][csg]") {
    checkSame(
        "flush pocket",
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {-0.5, 1.3, -0.5}, {0.5, 2.3, 0.5});
        },
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {-0.5, 1.3, -0.5}, {0.5, 3.3, 0.5});
        });
}

TEST_CASE("A slot through a box sharing its top, bottom, front and back", "[stress][csg]") {
    checkSame(
        "through slot",
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {-0.3, 0.3, -1}, {0.3, 2.3, 1});
        },
        [](SceneMaker& m, Materials mat) {
            return differenceOf(m, mat, {-0.3, -0.7, -2}, {0.3, 3.3, 2});
        });
}

TEST_CASE("An intersection of boxes sharing four face planes", "[stress][csg]") {
    auto intersection = [](DVec3 lo, DVec3 hi) {
        return [=](SceneMaker& m, Materials mat) {
            return m.csg(scene::CsgOp::Intersection, m.box(kLo, kHi, mat.a), m.box(lo, hi, mat.b));
        };
    };
    checkSame("intersection", intersection({0, 0.3, -1}, {2, 2.3, 1}),
              intersection({0, -0.7, -2}, {2, 3.3, 2}));
}

TEST_CASE("A union of two boxes sharing a face is one box", "[stress][csg]") {
    // Drawn on its own, and as the left operand of a difference (then CSG evaluates it: the
    // shared face is interior and the two top faces are one coplanar surface).
    auto halves = [](SceneMaker& m, Materials mat) {
        return m.csg(scene::CsgOp::Union, m.box(kLo, {0, 2.3, 1}, mat.a),
                     m.box({0, 0.3, -1}, kHi, mat.a));
    };
    auto whole = [](SceneMaker& m, Materials mat) { return m.box(kLo, kHi, mat.a); };
    checkSame("union drawn", halves, whole);
    auto bitten = [](auto solid) {
        return [=](SceneMaker& m, Materials mat) {
            int32_t bite = m.sphere({0, 2.3, -1}, 0.6, mat.b); // centred on the shared face's edge
            return m.csg(scene::CsgOp::Difference, solid(m, mat), bite);
        };
    };
    checkSame("union in a difference", bitten(halves), bitten(whole));
}

TEST_CASE("Coincident faces computed through different transforms", "[stress][csg]") {
    // Both operands turned 30° about y, the tool described around its own centre and moved into
    // place first: the shared planes agree only up to rounding.
    auto turned = [](DVec3 toolHalf, DVec3 toolCenter) {
        return [=](SceneMaker& m, Materials mat) {
            int32_t base = m.transformed(m.box(kLo, kHi, mat.a), {test::rotate({0, 30, 0})});
            int32_t tool = m.transformed(m.box(-toolHalf, toolHalf, mat.b),
                                         {test::translate(toolCenter), test::rotate({0, 30, 0})});
            return m.csg(scene::CsgOp::Difference, base, tool);
        };
    };
    checkSame("turned half removed", turned({0.5, 1, 1}, {0.5, 1.3, 0}),
              turned({1, 2, 2}, {1, 1.3, 0}));
}
