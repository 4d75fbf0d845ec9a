// Isosurface crossings against exact shapes: a sphere's function (every crossing of random
// lines, surface points within their bounds), a half-space closed by its box's faces, the open
// form, the evaluation limit and the gradient warning.
#include "geometry_test_support.hpp"

#include "tracer/geometry/isosurface.hpp"

#include <memory>

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;
using scene::FunctionOp;

namespace {

/// x² + y² + z² − r², as the front end compiles it: registers x y z, then r², then the rest.
std::shared_ptr<scene::FunctionProgram> sphereFunction(double radius) {
    auto f = std::make_shared<scene::FunctionProgram>();
    f->parameters = {"x", "y", "z"};
    f->constants = {radius * radius};
    f->code = {{FunctionOp::Mul, 4, 0, 0, 0}, {FunctionOp::Mul, 5, 1, 1, 1},
               {FunctionOp::Add, 4, 4, 5, 5}, {FunctionOp::Mul, 5, 2, 2, 2},
               {FunctionOp::Add, 4, 4, 5, 5}, {FunctionOp::Sub, 4, 4, 3, 3}};
    f->registerCount = 6;
    f->result = 4;
    return f;
}

/// `scale` · y: a plane whose gradient is `scale`.
std::shared_ptr<scene::FunctionProgram> planeFunction(double scale) {
    auto f = std::make_shared<scene::FunctionProgram>();
    f->parameters = {"x", "y", "z"};
    f->constants = {scale};
    f->code = {{FunctionOp::Mul, 4, 1, 3, 3}};
    f->registerCount = 5;
    f->result = 4;
    return f;
}

scene::IsosurfaceShape isosurface(std::shared_ptr<scene::FunctionProgram> f, double maxGradient,
                                  bool open = false, Vec3 lo = Vec3(-2), Vec3 hi = Vec3(2)) {
    auto desc = std::make_shared<scene::IsosurfaceDesc>();
    desc->function = std::move(f);
    desc->maxGradient = maxGradient;
    desc->boundsMin = lo;
    desc->boundsMax = hi;
    desc->open = open;
    return {desc};
}

} // namespace

TEST_CASE("isosurface: a sphere's function crosses random lines where the sphere does") {
    const double radius = 1.3;
    // |∇f| = 2|p| ≤ 2·2√3 in the box: a bound that holds everywhere finds every crossing.
    const IsosurfaceGeometry g(isosurface(sphereFunction(radius), 7));
    const SurfaceFn distance = [&](const LVec& p) { return length(p) - radius; };
    Random random(11);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Ray ray = random.lineThrough(random.inBox(1.5), 6);
        CrossingList list;
        g.crossLine(ray, list);
        checkAlternates(list, ray, [&](const LVec& p) { return length(p) < radius; }, true);
        // The exact sphere: a quadratic's roots.
        const Vec3 o = ray.origin, d = ray.dir;
        const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
        const double disc = b * b - a * c;
        if (disc <= 1e-9) continue; // tangent lines: either answer is right
        REQUIRE(list.count == 2);
        const double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
        CHECK(list[0].t == Approx(t0).margin(1e-9));
        CHECK(list[1].t == Approx(t1).margin(1e-9));
        for (int k = 0; k < 2; ++k) {
            const SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            CHECK(glm::length(sp.normal - glm::normalize(sp.point)) < 1e-6);
            checkBoundContainsExact(sp, ray, distance, list[k].t);
        }
        ++hits;
    }
    CHECK(hits > 100);
}

TEST_CASE("isosurface: the box's faces close the solid where the function is below the threshold") {
    const IsosurfaceGeometry g(isosurface(planeFunction(1), 1.1, false, Vec3(-1), Vec3(1)));
    CHECK(g.solid());
    // Along x below the plane: in through the face x = −1, out through x = 1.
    const Ray along{Vec3(-3, -0.5, 0.2), Vec3(1, 0, 0)};
    CrossingList list;
    g.crossLine(along, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(2));
    CHECK(list[1].t == Approx(4));
    CHECK(g.surfaceAt(along, list[0]).normal == Vec3(-1, 0, 0));
    CHECK(g.surfaceAt(along, list[1]).normal == Vec3(1, 0, 0));
    // Above the plane: nothing.
    CrossingList above;
    g.crossLine(Ray{Vec3(-3, 0.5, 0.2), Vec3(1, 0, 0)}, above);
    CHECK(above.count == 0);
    // Down through it: the plane, then the bottom face.
    const Ray down{Vec3(0.3, 3, 0.1), Vec3(0, -1, 0)};
    CrossingList through;
    g.crossLine(down, through);
    REQUIRE(through.count == 2);
    CHECK(through[0].t == Approx(3).margin(1e-12));
    CHECK(glm::length(g.surfaceAt(down, through[0]).normal - Vec3(0, 1, 0)) < 1e-9);
    CHECK(through[1].t == Approx(4));
    CHECK(g.surfaceAt(down, through[1]).normal == Vec3(0, -1, 0));
}

TEST_CASE("isosurface: an open one is the surface alone, and not a solid") {
    const IsosurfaceGeometry g(isosurface(planeFunction(1), 1.1, true, Vec3(-1), Vec3(1)));
    CHECK_FALSE(g.solid());
    CrossingList list;
    g.crossLine(Ray{Vec3(0.3, 3, 0.1), Vec3(0, -1, 0)}, list);
    REQUIRE(list.count == 1);
    CHECK(list[0].t == Approx(3).margin(1e-12));
    CrossingList along;
    g.crossLine(Ray{Vec3(-3, -0.5, 0.2), Vec3(1, 0, 0)}, along);
    CHECK(along.count == 0);
}

TEST_CASE("isosurface: a gradient above maxgradient is found and warned of, with the one to use") {
    // f = 5y: its gradient is 5, but maxgradient says 1.1.
    const IsosurfaceGeometry g(isosurface(planeFunction(5), 1.1, false, Vec3(-1), Vec3(1)));
    CrossingList list;
    g.crossLine(Ray{Vec3(0.3, 3, 0.1), Vec3(0, -1, 0)}, list);
    CHECK(g.findings().steepestGradient.load() == Approx(5));
    const std::string text = g.warnings("s.crt:3:5");
    CHECK_THAT(text, Catch::Contains("s.crt:3:5: warning: the function of this Isosurface changes by up to "
                                     "5.000 a unit, more than its maxgradient 1.1"));
    // A bound that holds, far above the gradient: the hint that it could be lower.
    const IsosurfaceGeometry loose(isosurface(planeFunction(1), 20, false, Vec3(-1), Vec3(1)));
    CrossingList again;
    loose.crossLine(Ray{Vec3(0.3, 3, 0.1), Vec3(0, -1, 0)}, again);
    CHECK(again.count == 2);
    CHECK_THAT(loose.warnings("s.crt:3:5"), Catch::Contains("far below its maxgradient 20"));
    // One that fits: no warning.
    const IsosurfaceGeometry fitting(isosurface(planeFunction(1), 1.1, false, Vec3(-1), Vec3(1)));
    CrossingList fits;
    fitting.crossLine(Ray{Vec3(0.3, 3, 0.1), Vec3(0, -1, 0)}, fits);
    CHECK(fitting.warnings("s.crt:3:5").empty());
}

TEST_CASE("isosurface: a search stops at the evaluation limit, and the lines cut short are counted") {
    const IsosurfaceGeometry g(isosurface(sphereFunction(1), 7), 10);
    CrossingList list;
    g.crossLine(Ray{Vec3(-5, 0.01, 0), Vec3(1, 0, 0)}, list);
    CHECK(g.findings().searchesCutShort.load() == 1);
    CHECK_THAT(g.warnings("s.crt:1:1"), Catch::Contains("along 1 line stopped after 10 evaluations"));
    const IsosurfaceGeometry enough(isosurface(sphereFunction(1), 7), 100'000);
    CrossingList all;
    enough.crossLine(Ray{Vec3(-5, 0.01, 0), Vec3(1, 0, 0)}, all);
    CHECK(all.count == 2);
    CHECK(enough.findings().searchesCutShort.load() == 0);
}

TEST_CASE("isosurface: the crossings in a window are those of all crossings there") {
    // A sphere cut by its box's top face, so that windows start and end inside the solid too.
    const IsosurfaceGeometry g(isosurface(sphereFunction(1.3), 7, false, Vec3(-2), Vec3(2, 0.8, 2)));
    Random random(17);
    int found = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random.lineThrough(random.inBox(1.2), 5);
        const double tMin = random.uniform(-1, 1.5), tMax = tMin + random.uniform(0.1, 3);
        CrossingList all;
        g.crossLine(ray, all);
        std::vector<Crossing> expected, visited;
        for (int k = 0; k < all.count; ++k)
            if (all[k].t > tMin && all[k].t < tMax) expected.push_back(all[k]);
        auto collect = [&](const Crossing& c) {
            visited.push_back(c);
            return true;
        };
        INFO("line " << i);
        CHECK(g.crossingsIn(ray, tMin, tMax, collect));
        REQUIRE(visited.size() == expected.size());
        for (size_t k = 0; k < visited.size(); ++k) {
            CHECK(visited[k].part == expected[k].part);
            CHECK(visited[k].t == Approx(expected[k].t).margin(1e-9));
        }
        // Stopped at the first: false, having visited it alone.
        int calls = 0;
        auto firstOnly = [&](const Crossing&) { return ++calls > 1; };
        CHECK(g.crossingsIn(ray, tMin, tMax, firstOnly) == expected.empty());
        CHECK(calls == (expected.empty() ? 0 : 1));
        if (!expected.empty()) ++found;
    }
    CHECK(found > 300);
}
