// Whole scenes moved 10⁶ units from the origin (camera, lights, objects) render as at home.
//
// Geometry is solved around each ray's closest approach and error bounds are relative to the
// coordinates, so the only cost of a far scene is the rounding of its coordinates (about
// 1e-10 of a unit at 10⁶): the 8-bit images may differ by more than 1/255 per channel on at
// most 0.1% of pixels (an edge pixel flipping), as for the scale tests.
#include "stress_scenes.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;

namespace {

constexpr int kWidth = 160, kHeight = 120;

/// Offsets of length about 10⁶: along a diagonal with coordinates that are not round, and
/// along one axis (where the other coordinates stay small).
const DVec3 kOffsets[] = {DVec3(612345.678, -487654.321, 623456.789), DVec3(0, 0, -1e6)};

/// Moves a scene by `offset` a second way: each drawn object wrapped in a translate modifier,
/// the camera and lights moved by hand.
scene::SceneDesc translatedByModifier(scene::SceneDesc desc, DVec3 offset) {
    desc.camera.position += offset;
    desc.camera.pointing += offset;
    for (scene::LightDesc& light : desc.lights) {
        light.origin += offset;
        light.from += offset;
        light.pointing += offset;
    }
    for (int32_t& root : desc.drawn) {
        scene::EntityDesc wrapper;
        wrapper.shape = scene::TransformNode{root, {test::translate(offset)}};
        desc.entities.push_back(wrapper);
        root = static_cast<int32_t>(desc.entities.size() - 1);
    }
    return desc;
}

/// At most 0.1% of the pixels may differ by more than 1/255 (19 of 160 × 120).
void checkSame(const PixelBuffer& moved, const PixelBuffer& home, const std::string& what) {
    const double allowed = 0.001 * home.width * home.height;
    ImageDiff diff = compare8bit(moved, home);
    INFO(what << ": " << diff.over << " pixels differ by more than 1/255 (allowed " << allowed
              << "), largest difference " << diff.worst << "/255 at " << diff.worstX << ","
              << diff.worstY << "; pixels over: " << diff.where);
    CHECK(diff.over <= allowed);
    WARN(what << ": largest difference " << diff.worst << "/255, " << diff.over
              << " pixels over 1/255 (allowed " << allowed << ") " << diff.where);
}

template <typename MakeScene>
void compareTranslated(const std::string& name, const MakeScene& make) {
    PixelBuffer home = test::renderOk(make(Placement{1, DVec3(0.0)}));
    for (DVec3 offset : kOffsets) {
        std::string where = " moved to (" + std::to_string(offset.x) + ", " +
                            std::to_string(offset.y) + ", " + std::to_string(offset.z) + ")";
        checkSame(test::renderOk(make(Placement{1, offset})), home, name + where);
        checkSame(test::renderOk(translatedByModifier(make(Placement{1, DVec3(0.0)}), offset)),
                  home, name + where + " by a translate modifier");
    }
}

/// A square plate 2e-4 thick (a pane of glass, in metres), seen nearly face-on; `csg`: cut out
/// of a cube by intersecting it with a thin slab, else a plain box.
scene::SceneDesc plate(DVec3 offset, bool csg) {
    test::SceneMaker m;
    m.desc = test::blankScene(96, 72, test::lookAt(offset + DVec3(0.3, 0.5, -4), offset, 40));
    int32_t mat = lambertMaterial(m, {0.8, 0.7, 0.3, 1});
    m.desc.lights.push_back(parallelLight(glm::normalize(DVec3(0.2, 0.5, -1))));
    const double thickness = 2e-4;
    if (csg) {
        int32_t cube = m.box(offset + DVec3(-1), offset + DVec3(1), mat);
        int32_t slab = m.box(offset + DVec3(-2, -2, 0), offset + DVec3(2, 2, thickness), mat);
        m.draw(m.csg(scene::CsgOp::Intersection, cube, slab));
    } else {
        m.draw(m.box(offset + DVec3(-1, -1, 0), offset + DVec3(1, 1, thickness), mat));
    }
    return m.desc;
}

} // namespace

TEST_CASE("Spheres and mirrors 1e6 from the origin render as at the origin",
          "[stress][translation]") {
    compareTranslated("mirror scene",
                      [](const Placement& at) { return mirrorScene(at, kWidth, kHeight); });
}

TEST_CASE("Every primitive 1e6 from the origin renders as at the origin", "[stress][translation]") {
    TempObjFile mesh = octahedronFile("translation_octahedron");
    compareTranslated("primitives scene", [&](const Placement& at) {
        return primitivesScene(at, kWidth, kHeight, mesh.path());
    });
}

TEST_CASE("A lit floor and sphere 1e6 from the origin have no shadow acne",
          "[stress][translation]") {
    // As the scale test's acne check: exact Lambert values, tolerance 1e-4 for float storage.
    constexpr double kTolerance = 1e-4;
    for (DVec3 offset : kOffsets) {
        LambertResult r = floorSphereLambert(Placement{1, offset}, kTolerance);
        INFO("offset (" << offset.x << ", " << offset.y << ", " << offset.z << "): " << r.wrong
                        << " of " << r.checked << " pixels differ from C·(n·l) by more than "
                        << kTolerance << "; largest difference " << r.worst);
        CHECK(r.wrong == 0);
        CHECK(r.checked > 2500);
    }
}

TEST_CASE("A thin plate 1e6 from the origin renders as at the origin", "[stress][translation]") {
    checkSame(test::renderOk(plate(kOffsets[0], false)), test::renderOk(plate(DVec3(0.0), false)),
              "plain box plate");
}

// CSG merges crossings closer than its coincidence window (render_scene.hpp,
// CsgRay::coincidence) into one event. The window grows with the ray origin's distance from
// the world origin; had it been wider than the plate (it was 1e-3 at 1e6 units once), the
// plate would lose both faces there, as a plain box never does.
TEST_CASE("A thin CSG plate 1e6 from the origin renders as at the origin",
          "[stress][translation]") {
    checkSame(test::renderOk(plate(kOffsets[0], true)), test::renderOk(plate(DVec3(0.0), true)),
              "CSG plate (cube ∩ slab)");
}
