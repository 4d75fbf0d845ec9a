// The scenes the scale and translation tests render at every size and place, and the
// analytic Lambert check of a lit floor and sphere.
#pragma once

#include "stress_util.hpp"

#include <string>

namespace crt::tracer::stress {

/// Where a unit-sized scene is put: world = offset + scale · p. Camera, lights and objects all
/// move, so every placement should give the same picture.
struct Placement {
    double scale = 1;
    DVec3 offset{0.0};

    DVec3 at(DVec3 p) const { return offset + scale * p; }
    double length(double l) const { return scale * l; }
};

inline ShadingMaterial shiny(scene::Color color, double reflectivity, double specular = 0) {
    ShadingMaterial m;
    m.color = color;
    m.reflectivity = reflectivity;
    m.diffuse = 1 - reflectivity;
    m.specular = specular;
    m.shininess = 20;
    return m;
}

/// Lights whose effect does not depend on the placement: a point light without falloff and a
/// parallel light (whose `from` and `pointing` move too, as a user moving a scene would).
inline void addStressLights(test::SceneMaker& m, const Placement& at, DVec3 pointLight,
                            scene::Color pointColor, scene::Color sunColor) {
    scene::LightDesc point;
    point.kind = scene::LightKind::Point;
    point.origin = at.at(pointLight);
    point.color = pointColor;
    m.desc.lights.push_back(point);
    scene::LightDesc sun;
    sun.kind = scene::LightKind::Parallel;
    sun.from = at.offset + DVec3(1, 3, -2);
    sun.pointing = at.offset;
    sun.color = sunColor;
    m.desc.lights.push_back(sun);
}

inline void gradientSky(scene::SceneDesc& desc) {
    desc.background.kind = scene::BackgroundKind::Gradient;
    desc.background.horizon = scene::Color{0.8, 0.85, 0.9, 1};
    desc.background.sky = scene::Color{0.3, 0.5, 0.9, 1};
}

/// x² + y² + z² − 1, as the front end compiles it: registers x y z, the constant, temporaries.
inline std::shared_ptr<scene::FunctionProgram> unitSphereFunction() {
    using Op = scene::FunctionOp;
    auto f = std::make_shared<scene::FunctionProgram>();
    f->parameters = {"x", "y", "z"};
    f->constants = {1};
    f->code = {{Op::Mul, 4, 0, 0, 0}, {Op::Mul, 5, 1, 1, 1}, {Op::Add, 4, 4, 5, 5},
               {Op::Mul, 5, 2, 2, 2}, {Op::Add, 4, 4, 5, 5}, {Op::Sub, 4, 4, 3, 3}};
    f->registerCount = 6;
    f->result = 4;
    return f;
}

/// 0.2 + 0.6 · x · (1 − z): heights in [0.2, 0.8] over the unit square.
inline std::shared_ptr<scene::FunctionProgram> slopeFunction() {
    using Op = scene::FunctionOp;
    auto f = std::make_shared<scene::FunctionProgram>();
    f->parameters = {"x", "y", "z"};
    f->constants = {1, 0.6, 0.2};
    f->code = {{Op::Sub, 6, 3, 2, 2}, {Op::Mul, 6, 0, 6, 6}, {Op::Mul, 6, 6, 4, 4},
               {Op::Add, 6, 6, 5, 5}};
    f->registerCount = 7;
    f->result = 6;
    return f;
}

/// A sphere resting on a slightly reflective floor, a mirror sphere and a mirror wall.
inline scene::SceneDesc mirrorScene(const Placement& at, int width, int height) {
    test::SceneMaker m;
    m.desc = test::blankScene(width, height,
                              test::lookAt(at.at({0.5, 2.2, -5}), at.at({0.3, 0.8, 0}), 50));
    m.desc.settings.recursionDepth = 5;
    gradientSky(m.desc);
    m.draw(m.plane({0, 1, 0}, at.at({0, 0, 0}), m.material(shiny({0.6, 0.6, 0.55, 1}, 0.2))));
    m.draw(m.sphere(at.at({0, 1, 0}), at.length(1),
                    m.material(shiny({0.8, 0.3, 0.2, 1}, 0, 0.4)))); // touches the floor
    m.draw(m.sphere(at.at({1.9, 0.8, 0.6}), at.length(0.8),
                    m.material(shiny({0.9, 0.9, 0.9, 1}, 0.9))));
    m.draw(m.plane({0, 0, -1}, at.at({0, 0, 4}), m.material(shiny({0.9, 0.9, 0.9, 1}, 0.7))));
    addStressLights(m, at, {-3, 5, -3}, {0.8, 0.8, 0.8, 1}, {0.3, 0.3, 0.3, 1});
    return m.desc;
}

/// An OBJ file of an octahedron of radius 0.5 around (−0.4, 0.6, −1.3), in the
/// primitives scene's unit coordinates.
inline TempObjFile octahedronFile(const std::string& name) {
    const DVec3 c(-0.4, 0.6, -1.3);
    std::vector<DVec3> v{c + DVec3(0.5, 0, 0), c - DVec3(0.5, 0, 0), c + DVec3(0, 0.5, 0),
                         c - DVec3(0, 0.5, 0), c + DVec3(0, 0, 0.5), c - DVec3(0, 0, 0.5)};
    std::vector<std::array<int, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                      {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return TempObjFile(name, v, f);
}

/// Every primitive users build, on a reflective floor in front of a mirror quad: box (resting
/// on the floor), cylinder, cone, torus, disc, triangle, a mesh and a rotated box (both placed
/// by modifiers), a superellipsoid (also placed by modifiers) and a box with a spherical dent
/// (CSG). `meshFile` is octahedronFile's.
inline scene::SceneDesc primitivesScene(const Placement& at, int width, int height,
                                        const std::string& meshFile) {
    using test::rotate, test::translate;
    test::SceneMaker m;
    m.desc = test::blankScene(width, height,
                              test::lookAt(at.at({0.3, 3.2, -7.5}), at.at({0, 0.7, 0.5}), 50));
    m.desc.settings.recursionDepth = 4;
    gradientSky(m.desc);
    auto mat = [&](double r, double g, double b, double reflect = 0, double spec = 0.3) {
        return m.material(shiny({r, g, b, 1}, reflect, spec));
    };
    auto add = [&](scene::Shape shape, int32_t material) { m.draw(m.entity(shape, material)); };
    const double s = at.scale;
    add(scene::PlaneShape{{0, 1, 0}, at.at({0, 0, 0})}, mat(0.6, 0.6, 0.55, 0.15, 0));
    add(scene::QuadShape{at.at({-3.5, 0, 2.5}), s * DVec3(7, 0, 0), s * DVec3(0, 2.5, 0.3)},
        mat(0.9, 0.9, 0.95, 0.5, 0));
    add(scene::BoxShape{at.at({-3.2, 0, 0}), at.at({-2, 1.2, 1.2})}, mat(0.8, 0.5, 0.2));
    add(scene::CylinderShape{at.at({-1.2, 0, 0.2}), at.at({-1.2, 1.5, 0.2}), s * 0.5, false},
        mat(0.2, 0.6, 0.8));
    add(scene::ConeShape{at.at({0.2, 0, 0.3}), s * 0.6, at.at({0.2, 1.4, 0.3}), s * 0.1, false},
        mat(0.3, 0.8, 0.3));
    add(scene::TorusShape{at.at({1.7, 0.35, 0}), s * 0.6, s * 0.25, DVec3(0.3, 1, 0.2)},
        mat(0.9, 0.8, 0.2, 0.3));
    add(scene::DiscShape{at.at({3.0, 0.8, 1.0}), DVec3(-0.5, 0.3, -1), s * 0.6, s * 0.15},
        mat(0.7, 0.2, 0.7));
    add(scene::TriangleShape{at.at({2.2, 0, -1.2}), at.at({3.4, 0, -0.6}), at.at({2.8, 1.4, -0.9})},
        mat(0.9, 0.4, 0.4));
    // Modifiers apply in order: unit placement, then the scale, then the offset.
    const scene::Modifier toWorld[] = {test::scale(DVec3(s)), translate(at.offset)};
    int32_t mesh = m.entity(scene::MeshShape{meshFile, meshFile}, mat(0.5, 0.5, 0.9, 0.2));
    m.draw(m.transformed(mesh, {toWorld[0], toWorld[1]}));
    int32_t cube = m.box(DVec3(-0.3), DVec3(0.3), mat(0.4, 0.7, 0.7));
    m.draw(m.transformed(
        cube, {rotate({0, 30, 0}), translate({-2.2, 0.3, -1.5}), toWorld[0], toWorld[1]}));
    // A superellipsoid with a pinched (star-shaped) profile, placed by modifiers like the cube.
    int32_t star = m.entity(scene::SuperellipsoidShape{0.4, 2.6}, mat(0.9, 0.6, 0.3, 0.2));
    m.draw(m.transformed(star, {test::scale(DVec3(0.4)), rotate({20, 30, 0}),
                                translate({0.3, 0.45, -2.9}), toWorld[0], toWorld[1]}));
    // A prism with a curved outline and a hole, swept to a point: walls, end faces and the
    // even-odd rule at every scale.
    scene::PrismShape prism;
    prism.spline = scene::SplineKind::Bezier;
    prism.points = {{0, -1},    {1.2, -1},   {1, 1},       {0, 1},      {0, 1},     {-1, 1},
                    {-1.2, -1}, {0, -1},     {0, -0.4},    {0.4, -0.4}, {0.4, 0.4}, {0, 0.4},
                    {0, 0.4},   {-0.4, 0.4}, {-0.4, -0.4}, {0, -0.4}};
    prism.conic = true;
    prism.from = 0.5;
    prism.to = 1.5;
    int32_t drop = m.entity(prism, mat(0.5, 0.8, 0.4, 0.2));
    m.draw(m.transformed(drop, {test::scale(DVec3(0.3)), rotate({-30, 20, 0}),
                                translate({-0.9, 0.2, -2.6}), toWorld[0], toWorld[1]}));
    // A vase as a surface of revolution, radius reaching the axis at its foot.
    int32_t vase = m.entity(
        scene::SorShape{{{0.2, -0.2}, {0, 0}, {0.8, 0.4}, {0.4, 1}, {0.6, 1.6}, {0.7, 1.8}}, false},
        mat(0.6, 0.5, 0.9, 0.2));
    m.draw(m.transformed(vase, {test::scale(DVec3(0.25)), rotate({10, 0, -15}),
                                translate({1.9, 0.05, -2.6}), toWorld[0], toWorld[1]}));
    // A ring as a lathe: a cubic curve closed on itself, turned about the axis.
    int32_t ring = m.entity(
        scene::LatheShape{
            {{0.6, 0.2}, {0.9, 0.5}, {0.6, 0.8}, {0.3, 0.5}, {0.6, 0.2}, {0.9, 0.5}, {0.6, 0.8}},
            scene::SplineKind::Cubic},
        mat(0.4, 0.7, 0.9, 0.2));
    m.draw(m.transformed(ring, {test::scale(DVec3(0.35)), rotate({-60, 0, 10}),
                                translate({-1.6, 0.1, -2.2}), toWorld[0], toWorld[1]}));
    // Text: glyph prisms of quadratic curves with holes, in the default font.
    auto text = std::make_shared<scene::TextDesc>();
    text->text = "e8";
    std::string fontError;
    if (auto outline =
            scene::layoutText(std::string(scene::kDefaultFontFile), text->text, 1, fontError))
        text->outline = std::make_shared<const scene::TextOutline>(std::move(*outline));
    int32_t label = m.entity(scene::TextShape{text}, mat(0.9, 0.9, 0.4, 0.2));
    m.draw(m.transformed(label, {test::scale(DVec3(0.4)), rotate({10, -20, 0}),
                                 translate({-0.4, -0.3, -2.4}), toWorld[0], toWorld[1]}));
    // A blob: two spheres and a cylinder blended, a negative sphere denting them.
    auto blob = std::make_shared<scene::BlobDesc>();
    blob->threshold = 0.5;
    blob->components = {{false, {-0.6, 0, 0}, {-0.6, 0, 0}, 1, 1},
                        {false, {0.6, 0, 0}, {0.6, 0, 0}, 1, 1},
                        {true, {0, -1, 0}, {0, 1.2, 0.3}, 0.5, 1.2},
                        {false, {0.3, 0.3, -0.6}, {0.3, 0.3, -0.6}, 0.5, -1}};
    int32_t drop2 = m.entity(scene::BlobShape{blob}, mat(0.5, 0.7, 0.9, 0.2));
    m.draw(m.transformed(drop2, {test::scale(DVec3(0.25)), rotate({-20, 30, 0}),
                                 translate({0.5, 0.6, -2.2}), toWorld[0], toWorld[1]}));
    // A sphere sweep: a cubic coil through five points, its radius changing.
    int32_t coil = m.entity(
        scene::SphereSweepShape{{{-1, 0, 0}, {-0.5, 0.8, 0.3}, {0, 0, 0.6}, {0.5, 0.8, 0.3},
                                 {1, 0, 0}, {1.2, 1, 0}},
                                {0.15, 0.2, 0.3, 0.2, 0.25, 0.15},
                                scene::SplineKind::Cubic},
        mat(0.9, 0.5, 0.6, 0.2));
    m.draw(m.transformed(coil, {test::scale(DVec3(0.35)), rotate({0, 20, 0}),
                                translate({1.2, 0.15, -1.6}), toWorld[0], toWorld[1]}));
    // An isosurface, a sphere's function with its top cut off by its box's face, and a smooth
    // height field sampled from a function: both searched in their own unit space.
    auto iso = std::make_shared<scene::IsosurfaceDesc>();
    iso->function = unitSphereFunction();
    iso->boundsMax = {1, 0.5, 1};
    iso->maxGradient = 4;
    int32_t bowl = m.entity(scene::IsosurfaceShape{iso}, mat(0.8, 0.4, 0.6, 0.2));
    m.draw(m.transformed(bowl, {test::scale(DVec3(0.3)), rotate({-40, 10, 0}),
                                translate({2.6, 0.35, -2.1}), toWorld[0], toWorld[1]}));
    auto field = std::make_shared<scene::HeightFieldDesc>();
    field->function = slopeFunction();
    field->resolution = 9;
    field->smooth = true;
    int32_t hill = m.entity(scene::HeightFieldShape{field}, mat(0.5, 0.8, 0.5, 0.2));
    m.draw(m.transformed(hill, {test::scale(DVec3(0.9, 0.5, 0.7)), rotate({0, 25, 0}),
                                translate({-3.0, 0.0, -2.3}), toWorld[0], toWorld[1]}));
    int32_t block = m.box(at.at({0.8, 0, -1.8}), at.at({1.6, 0.8, -1.0}), mat(0.8, 0.8, 0.8));
    int32_t dent = m.sphere(at.at({1.2, 0.8, -1.4}), s * 0.45, mat(0.9, 0.3, 0.3));
    m.draw(m.csg(scene::CsgOp::Difference, block, dent));
    addStressLights(m, at, {-2, 6, -4}, {0.7, 0.7, 0.7, 1}, {0.35, 0.35, 0.35, 1});
    return m.desc;
}

/// How many pixels of a lit floor with a sphere resting on it differ from the exact Lambert
/// value C·(n·l) (ambient 0, so a self-shadowed pixel is black), of how many checked.
struct LambertResult {
    int checked = 0;
    int wrong = 0;
    double worst = 0; ///< largest per-channel difference
};

/// Pixels in or near the sphere's shadow, at the silhouette (within 1e-3 of the radius) and at
/// the terminator (n·l < 0.05) are not checked: other tests look at those.
inline LambertResult floorSphereLambert(const Placement& at, double tolerance) {
    test::SceneMaker m;
    m.desc =
        test::blankScene(96, 72, test::lookAt(at.at({0.5, 2.2, -5}), at.at({0.3, 0.8, 0}), 50));
    const scene::Color color{0.7, 0.6, 0.5, 1};
    int32_t id = lambertMaterial(m, color);
    const DVec3 center = at.at({0, 1, 0}), floorPoint = at.at({0, 0, 0});
    const double radius = at.length(1);
    m.draw(m.plane({0, 1, 0}, floorPoint, id));
    m.draw(m.sphere(center, radius, id));
    const DVec3 l = glm::normalize(DVec3(-1, 4, -2));
    m.desc.lights.push_back(parallelLight(l));
    PixelBuffer image = test::renderOk(m.desc);
    LambertResult result;
    for (int y = 0; y < m.desc.settings.height; ++y) {
        for (int x = 0; x < m.desc.settings.width; ++x) {
            TestRay ray = test::specCameraRay(m.desc.camera, 96, 72, x, y);
            DVec3 n, p;
            if (auto t = test::hitSphere(ray, center, radius, 1e-3 * radius)) {
                p = ray.at(*t);
                n = (p - center) / radius;
            } else if (test::hitSphere(ray, center, radius + 1e-3 * radius)) {
                continue;
            } else if (auto tp = test::hitPlane(ray, {0, 1, 0}, floorPoint)) {
                p = ray.at(*tp);
                n = {0, 1, 0};
                DVec3 toCenter = center - p;
                double along = glm::dot(toCenter, l);
                if (along > 0 && glm::length(toCenter - along * l) < radius * 1.01) continue;
            } else {
                continue;
            }
            double cosTheta = glm::dot(n, l);
            if (cosTheta < 0.05) continue;
            double d =
                test::maxDifference(test::pixelAt(image, x, y), test::rgbOf(color) * cosTheta);
            result.worst = std::max(result.worst, d);
            result.wrong += d > tolerance;
            ++result.checked;
        }
    }
    return result;
}

} // namespace crt::tracer::stress
