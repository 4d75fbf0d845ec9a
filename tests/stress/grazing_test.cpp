// Grazing rays on every primitive: no holes, phantom hits or self-intersection speckles.
//
// Each primitive is seen three ways. (1) Zoomed onto a point of its silhouette, so that the
// pixel rays are within 10⁻³, 10⁻⁶ and 10⁻⁹ radians of tangent (or, for flat shapes, hit at a
// grazing angle next to the rim), with a flat emissive and half-mirror material on black:
// inside the analytic silhouette a pixel must be exactly the emission (darker is a hole,
// brighter is the surface reflecting itself), outside it exactly black. (2) The same views
// lit by a parallel light that also grazes the surface there (2% above its tangent plane), and
// (3) the whole shape lit so that its terminator, or for flat shapes the whole surface, is
// reached by shadow rays nearly tangent to it: every pixel that sees the surface must be the
// Lambert value C·(n·l), and a self-shadowed (acne) pixel is black.
#include "analytic_shapes.hpp"
#include "stress_scenes.hpp"

#include <functional>
#include <memory>
#include <string>

using namespace crt::tracer;
using namespace crt::tracer::stress;
namespace scene = crt::scene;
using test::SceneMaker;

namespace {

constexpr int kWidth = 96, kHeight = 72;
/// Coverage probes 1/100 pixel around each centre (see stress::coverage).
constexpr double kProbe = 0.01;
const scene::Color kEmission{0.2, 0.6, 0.9, 1};
const scene::Color kColor{0.8, 0.7, 0.6, 1};
/// Flat pixels must equal the emission up to float storage.
constexpr double kFlatTolerance = 1e-6;
/// Lit pixels: C·(n·l) up to float storage and the normal's rounding, far below the smallest
/// checked value (C·kMinCos ≈ 1.2e-3), which an acne pixel (0) misses entirely.
constexpr double kLitTolerance = 1e-5;
/// Pixels whose n·l is nearer 0 than this have an ambiguous sign and are not checked.
constexpr double kMinCos = 2e-3;

using HitFn = std::function<std::optional<SurfaceHit>(const TestRay&)>;

/// One primitive and where to look at it from.
struct GrazingCase {
    std::string name;
    std::function<void(SceneMaker&, int32_t)> add; ///< adds and draws it with a material
    HitFn hit;
    bool solid = true; ///< a sheet's normal is turned to face the viewer
    DVec3 camera;
    DVec3 inside;  ///< a point the camera's ray to it hits the shape on the way
    DVec3 outside; ///< one whose ray misses: a silhouette point lies between the two rays
    scene::CameraDesc overview;
    DVec3 overviewLight;               ///< unit, towards the light
    std::shared_ptr<TempObjFile> mesh; ///< keeps a mesh file alive while the case runs
};

/// A direction from the camera that grazes the silhouette: bisection between the rays to
/// `inside` and `outside`, kept on the hitting side.
DVec3 silhouetteDirection(const GrazingCase& c) {
    DVec3 in = glm::normalize(c.inside - c.camera), out = glm::normalize(c.outside - c.camera);
    REQUIRE(c.hit({c.camera, in}));
    REQUIRE_FALSE(c.hit({c.camera, out}));
    for (int i = 0; i < 200; ++i) {
        DVec3 mid = glm::normalize(in + out);
        if (mid == in || mid == out) break;
        (c.hit({c.camera, mid}) ? in : out) = mid;
    }
    return in;
}

/// The normal shading uses: a solid's outward one (the camera is outside, and at a tangent
/// hit the sign of n·d is rounding), a sheet's turned to face the ray's origin.
DVec3 facing(const GrazingCase& c, const SurfaceHit& hit, const TestRay& ray) {
    return !c.solid && glm::dot(hit.normal, ray.dir) > 0 ? -hit.normal : hit.normal;
}

scene::SceneDesc sceneWith(const GrazingCase& c, const scene::CameraDesc& camera, bool flat,
                           SceneMaker& m) {
    m.desc = test::blankScene(kWidth, kHeight, camera);
    c.add(m, flat ? flatMaterial(m, kEmission, 0.5) : lambertMaterial(m, kColor));
    return m.desc;
}

/// Check (1): holes, phantom hits and self-reflections in a flat-shaded view.
std::string checkSilhouette(const GrazingCase& c, const scene::CameraDesc& camera, double window) {
    SceneMaker m;
    scene::SceneDesc desc = sceneWith(c, camera, true, m);
    PixelBuffer image = test::renderOk(desc);
    const DVec3 e = test::rgbOf(kEmission);
    int inside = 0, outside = 0, holes = 0, phantoms = 0, speckles = 0;
    double worst = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            Coverage cover = coverage(desc, x, y, kProbe,
                                      [&](const TestRay& r) { return c.hit(r).has_value(); });
            DVec3 got = test::pixelAt(image, x, y);
            if (cover == Coverage::Inside) {
                ++inside;
                double d = test::maxDifference(got, e);
                worst = std::max(worst, d);
                if (d > kFlatTolerance) ++(got.z < e.z ? holes : speckles);
            } else if (cover == Coverage::Outside) {
                ++outside;
                double d = test::maxDifference(got, DVec3(0.0));
                worst = std::max(worst, d);
                phantoms += d > kFlatTolerance;
            }
        }
    }
    INFO(c.name << ", silhouette window " << window << " rad: " << inside << " pixels inside, "
                << outside << " outside; " << holes << " holes, " << phantoms << " phantom hits, "
                << speckles << " self-reflections; largest deviation " << worst << " (tolerance "
                << kFlatTolerance << ")");
    CHECK(inside > kWidth * kHeight / 8);
    CHECK(outside > kWidth * kHeight / 8);
    CHECK(holes == 0);
    CHECK(phantoms == 0);
    CHECK(speckles == 0);
    return "silhouette " + number(window) + ": " + std::to_string(inside) + " in, " +
           std::to_string(outside) + " out, worst " + number(worst) + "\n";
}

/// Checks (2) and (3): every pixel that surely sees the surface has its Lambert value, where
/// the expected shadowing comes from the analytic shape too (a torus shades itself).
std::string checkLit(const GrazingCase& c, const scene::CameraDesc& camera, DVec3 toLight,
                     const std::string& view) {
    SceneMaker m;
    scene::SceneDesc desc = sceneWith(c, camera, false, m);
    desc.lights.push_back(parallelLight(toLight));
    PixelBuffer image = test::renderOk(desc);
    int checked = 0, grazing = 0, acne = 0, other = 0;
    double worst = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            auto hits = [&](const TestRay& r) { return c.hit(r).has_value(); };
            if (coverage(desc, x, y, kProbe, hits) != Coverage::Inside) continue;
            TestRay ray = test::specCameraRay(desc.camera, kWidth, kHeight, x, y);
            SurfaceHit hit = *c.hit(ray);
            DVec3 n = facing(c, hit, ray);
            double cosL = glm::dot(n, toLight);
            if (std::abs(cosL) < kMinCos) continue;
            DVec3 p = ray.at(hit.t);
            double scale = 1 + glm::length(p);
            bool shadowed = cosL > 0 && c.hit({p + 1e-7 * scale * n, toLight}).has_value();
            DVec3 want = shadowed ? DVec3(0.0) : test::rgbOf(kColor) * std::max(0.0, cosL);
            DVec3 got = test::pixelAt(image, x, y);
            double d = test::maxDifference(got, want);
            worst = std::max(worst, d);
            ++checked;
            grazing += cosL > 0 && cosL < 0.05;
            if (d > kLitTolerance) ++(got.x < 0.5 * want.x ? acne : other);
        }
    }
    INFO(c.name << ", " << view << ": " << checked << " pixels checked (" << grazing
                << " lit at n·l < 0.05), " << acne << " self-shadowed, " << other
                << " otherwise wrong; largest deviation " << worst << " (tolerance "
                << kLitTolerance << ")");
    CHECK(checked > kWidth * kHeight / 10);
    CHECK(acne == 0);
    CHECK(other == 0);
    return "lit " + view + ": " + std::to_string(checked) + " checked, " + std::to_string(grazing) +
           " grazing, worst " + number(worst) + "\n";
}

void runGrazing(const GrazingCase& c) {
    DVec3 dir = silhouetteDirection(c);
    SurfaceHit at = *c.hit({c.camera, dir});
    DVec3 target = c.camera + at.t * dir;
    // A light 2% above the tangent plane at the silhouette point, across the view direction.
    DVec3 n = facing(c, at, {c.camera, dir});
    DVec3 tangent = glm::normalize(glm::cross(n, dir));
    DVec3 grazingLight = glm::normalize(0.02 * n + tangent);
    std::string summary = c.name + ":\n";
    for (double window : {1e-3, 1e-6, 1e-9}) {
        scene::CameraDesc camera = zoomedCamera(c.camera, target, window * at.t);
        summary += checkSilhouette(c, camera, window);
        summary += checkLit(c, camera, grazingLight, "zoomed " + number(window));
    }
    summary += checkLit(c, c.overview, c.overviewLight, "overview");
    WARN(summary);
}

// --- the primitives ---------------------------------------------------------------------

GrazingCase sphereCase() {
    const DVec3 center(0.1, 0.2, 0.3);
    const double radius = 1;
    GrazingCase c;
    c.name = "sphere";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.sphere(center, radius, mat)); };
    c.hit = [=](const TestRay& r) { return sphereHit(r, center, radius); };
    c.camera = DVec3(0.7, 1.3, -4.5);
    c.inside = center;
    c.outside = center + DVec3(3, 0, 0);
    c.overview = test::lookAt(c.camera, center, 35);
    c.overviewLight = glm::normalize(DVec3(1, 0.2, 0.1));
    return c;
}

/// The sphere as a blob: one component whose field passes the threshold at radius 1.
GrazingCase blobCase() {
    GrazingCase c = sphereCase();
    const DVec3 center = c.inside;
    // strength · (1 − (d/r)²)² = 0.25 at d = r·√(1 − √0.25) = r·√0.5: r = √2 gives 1.
    auto blob = std::make_shared<scene::BlobDesc>();
    blob->threshold = 0.25;
    blob->components = {{false, center, center, std::sqrt(2.0), 1}};
    c.name = "blob";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.entity(scene::BlobShape{blob}, mat)); };
    return c;
}

/// The sphere as an isosurface of x² + y² + z² − 1, moved to its centre, with an accuracy
/// fine enough to part the two crossings of the nearest lines to the tangent the test casts (a
/// billionth of the distance off it).
GrazingCase isosurfaceCase() {
    GrazingCase c = sphereCase();
    auto iso = std::make_shared<scene::IsosurfaceDesc>();
    iso->function = unitSphereFunction();
    iso->boundsMin = DVec3(-1.1);
    iso->boundsMax = DVec3(1.1);
    iso->maxGradient = 3.85; // 2·|p|, at most 2·1.1·√3
    iso->accuracy = 1e-7;
    const DVec3 center = c.inside;
    c.name = "isosurface";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.transformed(m.entity(scene::IsosurfaceShape{iso}, mat), {test::translate(center)}));
    };
    return c;
}

GrazingCase boxCase() {
    const DVec3 lo(-1, -0.5, -0.7), hi(0.8, 0.6, 0.9);
    GrazingCase c;
    c.name = "box";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.box(lo, hi, mat)); };
    c.hit = [=](const TestRay& r) { return boxHit(r, lo, hi); };
    // Just above the top face's plane: its far edge is seen at a 0.3° grazing angle.
    c.camera = DVec3(0.2, hi.y + 0.03, -5);
    c.inside = 0.5 * (lo + hi);
    c.outside = DVec3(0.2, 1.5, hi.z);
    // From higher up, so that the top face lit 1° above its plane fills many pixels.
    c.overview = test::lookAt(DVec3(0.6, 2.5, -4), 0.5 * (lo + hi), 35);
    c.overviewLight = glm::normalize(DVec3(0.3, 0.02, -1));
    return c;
}

/// The box above as a prism whose sides are Bézier segments with their handles on the sides:
/// straight walls, found by the curve code (the rounded coefficients leave the cubic terms
/// tiny rather than zero), and end faces read through the curved outline.
GrazingCase prismCase() {
    GrazingCase c = boxCase();
    const DVec3 lo(-1, -0.5, -0.7), hi(0.8, 0.6, 0.9);
    scene::PrismShape prism;
    prism.spline = scene::SplineKind::Bezier;
    const glm::dvec2 corners[] = {{lo.x, lo.z}, {hi.x, lo.z}, {hi.x, hi.z}, {lo.x, hi.z}};
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 a = corners[i], b = corners[(i + 1) % 4];
        prism.points.insert(prism.points.end(), {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
    }
    prism.from = lo.y;
    prism.to = hi.y;
    c.name = "prism";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.entity(prism, mat)); };
    return c;
}

GrazingCase planeCase() {
    const DVec3 normal = glm::normalize(DVec3(0.1, 1, -0.15)), point(0.3, -1, 0.2);
    DVec3 u, v;
    completeFrame(normal, u, v);
    GrazingCase c;
    c.name = "plane";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.plane(normal, point, mat)); };
    c.hit = [=](const TestRay& r) { return planeHit(r, normal, point); };
    c.solid = false; // two-sided for shading
    // The silhouette is the horizon: rays just below it meet the plane arbitrarily far away.
    c.camera = point + normal - 3.0 * v;
    c.inside = point + 5.0 * v;
    c.outside = c.inside + 3.0 * normal;
    c.overview = test::lookAt(c.camera, point + 4.0 * v, 40);
    c.overviewLight = glm::normalize(0.01 * normal + u); // 0.6° above the plane
    return c;
}

/// A direction across the view from `camera` to `at`, perpendicular to `axis`.
DVec3 across(DVec3 camera, DVec3 at, DVec3 axis) {
    return glm::normalize(glm::cross(axis, at - camera));
}

GrazingCase cylinderCase() {
    const DVec3 base(-0.2, -1, 0.1), top(0.3, 1, -0.2);
    const double radius = 0.7;
    const DVec3 middle = 0.5 * (base + top);
    GrazingCase c;
    c.name = "cylinder";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::CylinderShape{base, top, radius, false}, mat));
    };
    c.hit = [=](const TestRay& r) { return axialHit(r, base, top, radius, radius); };
    c.camera = DVec3(0.5, 0.8, -5);
    c.inside = middle;
    c.outside = middle + 3.0 * across(c.camera, middle, top - base); // the side's silhouette
    c.overview = test::lookAt(c.camera, middle, 40);
    c.overviewLight = glm::normalize(DVec3(1, 0.1, 0.05)); // terminator along the side
    return c;
}

GrazingCase coneCase() {
    const DVec3 base(0.1, -1, 0), top(-0.1, 1, 0.2);
    const double r0 = 1, r1 = 0.25;
    const DVec3 middle = 0.5 * (base + top);
    GrazingCase c;
    c.name = "cone";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::ConeShape{base, r0, top, r1, false}, mat));
    };
    c.hit = [=](const TestRay& r) { return axialHit(r, base, top, r0, r1); };
    c.camera = DVec3(-0.4, 0.9, -5);
    c.inside = middle;
    c.outside = middle + 3.0 * across(c.camera, middle, top - base);
    c.overview = test::lookAt(c.camera, middle, 40);
    c.overviewLight = glm::normalize(DVec3(-1, 0.3, 0.1));
    return c;
}

/// A cone as a surface of revolution: four points on one line make R(y) the square of a
/// linear radius, which the cubic reproduces, with the end faces.
GrazingCase sorCase() {
    const DVec3 base(0, -1, 0), top(0, 1, 0);
    const double r0 = 1, r1 = 0.25;
    auto radius = [=](double y) { return r0 + (r1 - r0) * (y + 1) / 2; };
    scene::SorShape sor;
    for (double y : {-1.5, -1.0, 1.0, 1.5}) sor.points.push_back({radius(y), y});
    GrazingCase c;
    c.name = "sor";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.entity(sor, mat)); };
    c.hit = [=](const TestRay& r) { return axialHit(r, base, top, r0, r1); };
    c.camera = DVec3(-0.4, 0.9, -5);
    c.inside = DVec3(0.0);
    c.outside = 3.0 * across(c.camera, DVec3(0.0), top - base);
    c.overview = test::lookAt(c.camera, DVec3(0.0), 40);
    c.overviewLight = glm::normalize(DVec3(-1, 0.3, 0.1));
    return c;
}

/// A capsule as a sphere sweep: a straight segment of one radius, its spheres' envelope a
/// cylinder between two half spheres. `cubic` makes it a Catmull-Rom piece of four evenly
/// spaced points on the line (the rounded coefficients leave the cubic terms tiny rather than
/// zero), found by the cubic segments' code.
GrazingCase sphereSweepCase(bool cubic) {
    const DVec3 base(-0.2, -1, 0.1), top(0.3, 1, -0.2);
    const double radius = 0.6;
    const DVec3 middle = 0.5 * (base + top);
    scene::SphereSweepShape sweep;
    if (cubic) {
        sweep.points = {2.0 * base - top, base, top, 2.0 * top - base};
        sweep.radii = {radius, radius, radius, radius};
        sweep.spline = scene::SplineKind::Cubic;
    } else {
        sweep.points = {base, top};
        sweep.radii = {radius, radius};
    }
    GrazingCase c;
    c.name = cubic ? "cubic sphere sweep" : "sphere sweep";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.entity(sweep, mat)); };
    c.hit = [=](const TestRay& r) {
        std::optional<SurfaceHit> nearest;
        for (auto hit : {sphereHit(r, base, radius), sphereHit(r, top, radius),
                         axialHit(r, base, top, radius, radius)}) {
            if (hit && (!nearest || hit->t < nearest->t)) nearest = hit;
        }
        return nearest;
    };
    c.camera = DVec3(0.5, 0.8, -5);
    c.inside = middle;
    c.outside = middle + 3.0 * across(c.camera, middle, top - base);
    c.overview = test::lookAt(c.camera, middle, 40);
    c.overviewLight = glm::normalize(DVec3(1, 0.1, 0.05));
    return c;
}

/// A cone as a lathe: a straight curve from the axis round the cone's outline back to it.
GrazingCase latheCase() {
    const DVec3 base(0, -1, 0), top(0, 1, 0);
    const double r0 = 1, r1 = 0.25;
    scene::LatheShape lathe{{{0, -1}, {r0, -1}, {r1, 1}, {0, 1}}, scene::SplineKind::Linear};
    GrazingCase c;
    c.name = "lathe";
    c.add = [=](SceneMaker& m, int32_t mat) { m.draw(m.entity(lathe, mat)); };
    c.hit = [=](const TestRay& r) { return axialHit(r, base, top, r0, r1); };
    c.camera = DVec3(0.4, 0.9, -5);
    c.inside = DVec3(0.0);
    c.outside = 3.0 * across(c.camera, DVec3(0.0), top - base);
    c.overview = test::lookAt(c.camera, DVec3(0.0), 40);
    c.overviewLight = glm::normalize(DVec3(1, 0.3, 0.1));
    return c;
}

GrazingCase torusCase() {
    const DVec3 center(0, 0.1, 0), axis = glm::normalize(DVec3(0.2, 1, -0.1));
    const double major = 1, minor = 0.3;
    GrazingCase c;
    c.name = "torus";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::TorusShape{center, major, minor, axis}, mat));
    };
    c.hit = [=](const TestRay& r) { return torusHit(r, center, major, minor, axis); };
    c.camera = DVec3(0.4, 1.6, -4.5); // above the equator: the hole is visible
    DVec3 side = across(c.camera, center, axis);
    c.inside = center + major * side; // the tube's centre circle
    c.outside = center + (major + 2.5 * minor) * side;
    c.overview = test::lookAt(c.camera, center, 40);
    // Nearly along the axis: the terminator runs along the tube's two equators, so shadow rays
    // leave the tube nearly tangent; where the ring shades itself, the expectation's shadow
    // test says so.
    c.overviewLight = glm::normalize(axis + DVec3(0.05, 0, 0.1));
    return c;
}

/// A camera at a grazing elevation above a flat shape at `center` with unit normal `normal`:
/// `distance` away along the plane, `height` above it.
DVec3 grazingViewpoint(DVec3 center, DVec3 normal, double distance, double height) {
    DVec3 u, v;
    completeFrame(normal, u, v);
    return center - distance * glm::normalize(u + 0.3 * v) + height * normal;
}

GrazingCase discCase() {
    const DVec3 center(0.2, -0.1, 0.3), normal = glm::normalize(DVec3(0.15, 1, 0.1));
    const double radius = 1;
    GrazingCase c;
    c.name = "disc";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::DiscShape{center, normal, radius, 0}, mat));
    };
    c.hit = [=](const TestRay& r) { return discHit(r, center, normal, radius); };
    c.solid = false;
    c.camera = grazingViewpoint(center, normal, 5, 0.05); // the far rim at about 0.5°
    c.inside = center;
    c.outside = center + 0.5 * normal;
    c.overview = test::lookAt(grazingViewpoint(center, normal, 4, 1.2), center, 25);
    DVec3 u, v;
    completeFrame(normal, u, v);
    c.overviewLight = glm::normalize(0.01 * normal + v); // 0.6° above the disc
    return c;
}

GrazingCase quadCase() {
    const DVec3 corner(-0.8, -0.1, -0.6), edgeA(1.7, 0.1, 0.2), edgeB(-0.1, 0.2, 1.5);
    const DVec3 normal = glm::normalize(glm::cross(edgeA, edgeB));
    const DVec3 center = corner + 0.5 * (edgeA + edgeB);
    GrazingCase c;
    c.name = "quad";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::QuadShape{corner, edgeA, edgeB}, mat));
    };
    c.hit = [=](const TestRay& r) { return quadHit(r, corner, edgeA, edgeB); };
    c.solid = false;
    c.camera = grazingViewpoint(center, normal, 5, 0.04);
    c.inside = center;
    c.outside = center + 0.5 * normal;
    c.overview = test::lookAt(grazingViewpoint(center, normal, 4, 1.2), center, 25);
    c.overviewLight = glm::normalize(0.01 * normal + glm::normalize(edgeA));
    return c;
}

GrazingCase triangleCase() {
    const DVec3 a(-0.9, 0, -0.5), b(1, 0.15, -0.3), tip(0.1, -0.1, 1.2);
    const DVec3 normal = glm::normalize(glm::cross(b - a, tip - a));
    const DVec3 center = (a + b + tip) / 3.0;
    GrazingCase c;
    c.name = "triangle";
    c.add = [=](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::TriangleShape{a, b, tip}, mat));
    };
    c.hit = [=](const TestRay& r) { return triangleHit(r, a, b, tip); };
    c.solid = false;
    c.camera = grazingViewpoint(center, normal, 5, 0.04);
    c.inside = center;
    c.outside = center + 0.5 * normal;
    c.overview = test::lookAt(grazingViewpoint(center, normal, 3, 0.9), center, 25);
    c.overviewLight = glm::normalize(0.01 * normal + glm::normalize(b - a));
    return c;
}

/// A flat 8 × 8 grid of cells, two triangles each, over a tilted parallelogram: at grazing
/// angles most pixel rays cross the mesh near a shared edge.
GrazingCase meshCase() {
    const DVec3 corner(-0.9, 0.05, -0.7), edgeA(1.8, -0.15, 0.1), edgeB(0.05, 0.25, 1.6);
    const DVec3 normal = glm::normalize(glm::cross(edgeA, edgeB));
    const DVec3 center = corner + 0.5 * (edgeA + edgeB);
    constexpr int kCells = 8;
    std::vector<DVec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i)
            vertices.push_back(corner + (double(i) / kCells) * edgeA +
                               (double(j) / kCells) * edgeB);
    for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) {
            int v00 = j * (kCells + 1) + i, v10 = v00 + 1, v01 = v00 + kCells + 1, v11 = v01 + 1;
            triangles.push_back({v00, v10, v11});
            triangles.push_back({v00, v11, v01});
        }
    }
    GrazingCase c;
    c.name = "mesh";
    c.mesh = std::make_shared<TempObjFile>("grazing_grid", vertices, triangles);
    c.add = [file = c.mesh->path()](SceneMaker& m, int32_t mat) {
        m.draw(m.entity(scene::MeshShape{file, file}, mat));
    };
    // The outline: the grid's corners are exactly those of this parallelogram.
    c.hit = [=](const TestRay& r) { return quadHit(r, corner, edgeA, edgeB); };
    c.solid = false;
    c.camera = grazingViewpoint(center, normal, 5, 0.04);
    c.inside = center;
    c.outside = center + 0.5 * normal;
    // A grazing camera as well (3°, zoomed so the thin grid fills half the image): rays cross
    // the grid's shared edges nearly along the surface.
    c.overview = test::lookAt(grazingViewpoint(center, normal, 3, 0.15), center, 3);
    c.overviewLight = glm::normalize(0.01 * normal + glm::normalize(edgeB));
    return c;
}

} // namespace

TEST_CASE("Grazing rays on a sphere", "[stress][grazing]") {
    runGrazing(sphereCase());
}
TEST_CASE("Grazing rays on a blob", "[stress][grazing]") {
    runGrazing(blobCase());
}
TEST_CASE("Grazing rays on an isosurface", "[stress][grazing][release-only]") {
    runGrazing(isosurfaceCase());
}
TEST_CASE("Grazing rays on a box", "[stress][grazing]") {
    runGrazing(boxCase());
}
TEST_CASE("Grazing rays on a prism", "[stress][grazing]") {
    runGrazing(prismCase());
}
TEST_CASE("Grazing rays on a plane", "[stress][grazing]") {
    runGrazing(planeCase());
}
TEST_CASE("Grazing rays on a cylinder", "[stress][grazing]") {
    runGrazing(cylinderCase());
}
TEST_CASE("Grazing rays on a cone", "[stress][grazing]") {
    runGrazing(coneCase());
}
TEST_CASE("Grazing rays on a surface of revolution", "[stress][grazing]") {
    runGrazing(sorCase());
}
TEST_CASE("Grazing rays on a sphere sweep", "[stress][grazing]") {
    runGrazing(sphereSweepCase(false));
}
TEST_CASE("Grazing rays on a cubic sphere sweep", "[stress][grazing]") {
    runGrazing(sphereSweepCase(true));
}
TEST_CASE("Grazing rays on a lathe", "[stress][grazing]") {
    runGrazing(latheCase());
}
TEST_CASE("Grazing rays on a torus", "[stress][grazing]") {
    runGrazing(torusCase());
}
TEST_CASE("Grazing rays on a disc", "[stress][grazing]") {
    runGrazing(discCase());
}
TEST_CASE("Grazing rays on a quad", "[stress][grazing]") {
    runGrazing(quadCase());
}
TEST_CASE("Grazing rays on a triangle", "[stress][grazing]") {
    runGrazing(triangleCase());
}
TEST_CASE("Grazing rays on mesh triangles", "[stress][grazing]") {
    runGrazing(meshCase());
}
