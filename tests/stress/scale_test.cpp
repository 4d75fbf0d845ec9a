// Numerical stability across scales: scenes from 1e-6 to 1e9 units look like the unit scene.
//
// Spawned rays are offset by a bound on the hit point's error, not a fixed epsilon (spec §6,
// "Robustness"), and every light here is scale-free, so a scene scaled uniformly must look
// the same at every scale: the 8-bit images may differ by more than 1/255 per channel on at
// most 0.1% of pixels (rounding of the scaled coordinates can flip a pixel at an edge, nothing
// more). Acne (a surface shadowing or reflecting itself) would flip whole patches.
#include "stress_scenes.hpp"

#include <catch2/catch.hpp>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;

namespace {

constexpr int kWidth = 160, kHeight = 120;
/// Pixels allowed to differ by more than 1/255: 0.1% of the image (19 of 19,200).
constexpr double kAllowedPixels = 0.001 * kWidth * kHeight;
constexpr double kScales[] = {1e-6, 1e-3, 1e3, 1e6, 1e9};

template <typename MakeScene> void compareScales(const char* name, const MakeScene& make) {
    PixelBuffer unit = test::renderOk(make(Placement{1, DVec3(0.0)}));
    for (double s : kScales) {
        ImageDiff diff = compare8bit(test::renderOk(make(Placement{s, DVec3(0.0)})), unit);
        INFO(name << " at scale " << s << ": " << diff.over
                  << " pixels differ by more than 1/255 (allowed " << kAllowedPixels
                  << "), largest difference " << diff.worst << "/255 at " << diff.worstX << ","
                  << diff.worstY << "; pixels over: " << diff.where);
        CHECK(diff.over <= kAllowedPixels);
        WARN(name << " at scale " << s << ": largest difference " << diff.worst << "/255, "
                  << diff.over << " pixels over 1/255 (allowed " << kAllowedPixels << ") "
                  << diff.where);
    }
}

} // namespace

TEST_CASE("Spheres and mirrors at scales 1e-6 to 1e9 render like the unit scene",
          "[stress][scale]") {
    compareScales("mirror scene",
                  [](const Placement& at) { return mirrorScene(at, kWidth, kHeight); });
}

TEST_CASE("Every primitive at scales 1e-6 to 1e9 renders like the unit scene", "[stress][scale]") {
    TempObjFile mesh = octahedronFile("scale_octahedron");
    compareScales("primitives scene", [&](const Placement& at) {
        return primitivesScene(at, kWidth, kHeight, mesh.path());
    });
}

TEST_CASE("A lit floor and sphere have no shadow acne at scales 1e-6 to 1e9", "[stress][scale]") {
    // Exact Lambert values wherever a point sees the light, so a single self-shadowed (acne)
    // pixel fails, at every scale; the tolerance 1e-4 absorbs float storage only.
    constexpr double kTolerance = 1e-4;
    for (double s : {1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9}) {
        LambertResult r = floorSphereLambert(Placement{s, DVec3(0.0)}, kTolerance);
        INFO("scale " << s << ": " << r.wrong << " of " << r.checked
                      << " pixels differ from C·(n·l) by more than " << kTolerance
                      << "; largest difference " << r.worst);
        CHECK(r.wrong == 0);
        CHECK(r.checked > 2500);
        WARN("acne check at scale " << s << ": largest difference " << r.worst << " (tolerance "
                                    << kTolerance << ")");
    }
}
