// Height field crossings against the exact piecewise-linear solid in long double: random
// grids and random lines, lines through grid points and along edges and diagonals (no gap
// between triangles or cells), a tilted plane's exact hits and normals, and smooth normals.
#include "geometry_test_support.hpp"

#include "tracer/geometry/height_field.hpp"

#include <memory>

using namespace crt::tracer;
using namespace crt::tracer::test;

namespace {

std::shared_ptr<HeightGrid> gridOf(int columns, int rows, const std::function<double(double, double)>& h) {
    auto grid = std::make_shared<HeightGrid>();
    grid->columns = columns;
    grid->rows = rows;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            grid->heights.push_back(static_cast<float>(h(double(i) / (columns - 1), double(j) / (rows - 1))));
    return grid;
}

/// The surface's height from its definition, in long double: the cell's triangle (diagonal
/// from (i + 1, j) to (i, j + 1)) through its three corners.
LD exactHeight(const HeightGrid& g, LD x, LD z) {
    const LD gx = std::clamp<LD>(x, 0, 1) * (g.columns - 1), gz = std::clamp<LD>(z, 0, 1) * (g.rows - 1);
    const int i = std::min(static_cast<int>(gx), g.columns - 2), j = std::min(static_cast<int>(gz), g.rows - 2);
    const LD fx = gx - i, fz = gz - j;
    if (fx + fz <= 1) return g.at(i, j) + (LD(g.at(i + 1, j)) - g.at(i, j)) * fx + (LD(g.at(i, j + 1)) - g.at(i, j)) * fz;
    return g.at(i + 1, j + 1) + (LD(g.at(i, j + 1)) - g.at(i + 1, j + 1)) * (1 - fx) +
           (LD(g.at(i + 1, j)) - g.at(i + 1, j + 1)) * (1 - fz);
}

bool exactInside(const HeightGrid& g, const LVec& p) {
    return p.x > 0 && p.x < 1 && p.z > 0 && p.z < 1 && p.y > 0 && p.y < exactHeight(g, p.x, p.z);
}

} // namespace

TEST_CASE("height field: random grids cross random lines as the exact solid does") {
    Random random(5);
    for (int trial = 0; trial < 6; ++trial) {
        const int columns = 2 + trial * 3, rows = 2 + trial * 2;
        auto grid = gridOf(columns, rows, [&](double, double) { return random.uniform(0.05, 1); });
        const HeightFieldGeometry g(grid, false);
        for (int i = 0; i < 400; ++i) {
            const Ray ray = random.lineThrough(random.pointIn(g.bounds()), 4);
            CrossingList list;
            g.crossLine(ray, list);
            INFO("trial " << trial << " line " << i);
            checkAlternates(list, ray, [&](const LVec& p) { return exactInside(*grid, p); }, true);
            for (int k = 0; k < list.count; ++k) {
                const SurfacePoint sp = g.surfaceAt(ray, list[k]);
                checkUnit(sp.normal);
                if (list[k].part != 0) continue;
                // On the surface, to rounding.
                CHECK(std::abs(LD(sp.point.y) - exactHeight(*grid, sp.point.x, sp.point.z)) < 1e-9L);
            }
        }
    }
}

TEST_CASE("height field: lines through grid points, along cell edges and diagonals leave no gap") {
    auto grid = gridOf(6, 5, [](double x, double z) { return 0.4 + 0.5 * x * x + 0.3 * std::sin(7 * z); });
    const HeightFieldGeometry g(grid, false);
    // Vertical lines through every grid point and the middles of edges and diagonals: one
    // crossing of the surface, then the bottom.
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 6; ++i) {
            for (auto [dx, dz] : {std::pair{0.0, 0.0}, {0.5, 0.0}, {0.0, 0.5}, {0.5, 0.5}}) {
                const double x = std::min(1.0, (i + dx) / 5), z = std::min(1.0, (j + dz) / 4);
                if (x <= 0 || x >= 1 || z <= 0 || z >= 1) continue;
                const Ray down{Vec3(x, 2, z), Vec3(0, -1, 0)};
                CrossingList list;
                g.crossLine(down, list);
                INFO("x " << x << " z " << z);
                REQUIRE(list.count == 2);
                CHECK(double(2 - list[0].t) == Approx(double(exactHeight(*grid, x, z))).margin(1e-12));
                CHECK(list[1].t == Approx(2));
            }
        }
    }
    // Slanted lines in the planes of the grid lines and of the diagonals.
    Random random(9);
    for (int i = 0; i < 300; ++i) {
        const double c = std::round(random.uniform(1, 4)) / 5;
        const Vec3 from(c, random.uniform(1.5, 2), -0.5), to(c, random.uniform(-0.5, 0.5), 1.5);
        const Vec3 along(random.uniform(-0.5, 1.5), 2, random.uniform(-0.5, 1.5));
        for (const Ray& ray : {Ray{from, to - from}, Ray{along, Vec3(1, -1.3, -1)}}) {
            CrossingList list;
            g.crossLine(ray, list);
            checkAlternates(list, ray, [&](const LVec& p) { return exactInside(*grid, p); }, true);
        }
    }
}

TEST_CASE("height field: a tilted plane's heights give its exact hits and normal") {
    auto grid = gridOf(7, 9, [](double x, double z) { return 0.25 + 0.5 * x - 0.125 * z; });
    const HeightFieldGeometry g(grid, false);
    const Vec3 normal = glm::normalize(Vec3(-0.5, 1, 0.125));
    Random random(3);
    for (int i = 0; i < 200; ++i) {
        const double x = random.uniform(0.01, 0.9), z = random.uniform(0.01, 0.9);
        const Ray ray{Vec3(x, 3, z) - Vec3(0.1, 0, 0.05) * 2.0, Vec3(0.1, -1, 0.05)};
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count >= 1);
        REQUIRE(list[0].part == 0);
        const SurfacePoint sp = g.surfaceAt(ray, list[0]);
        CHECK(glm::length(sp.normal - normal) < 1e-6);
        // The heights are floats: the plane to their precision, the grid's surface exactly.
        CHECK(sp.point.y == Approx(0.25 + 0.5 * sp.point.x - 0.125 * sp.point.z).margin(1e-7));
        const SurfaceFn plane = [&](const LVec& p) { return (p.y - exactHeight(*grid, p.x, p.z)) * LD(normal.y); };
        checkBoundContainsExact(sp, ray, plane, list[0].t);
    }
}

TEST_CASE("height field: smooth normals follow a smooth surface's") {
    auto grid = gridOf(41, 41, [](double x, double z) { return 0.5 + 0.2 * std::sin(3 * x) * std::cos(2 * z); });
    grid->computeNormals();
    const HeightFieldGeometry g(grid, true);
    Random random(21);
    for (int i = 0; i < 100; ++i) {
        const double x = random.uniform(0.05, 0.95), z = random.uniform(0.05, 0.95);
        const Ray down{Vec3(x, 2, z), Vec3(0, -1, 0)};
        CrossingList list;
        g.crossLine(down, list);
        REQUIRE(list.count == 2);
        const SurfacePoint sp = g.surfaceAt(down, list[0]);
        const Vec3 exact = glm::normalize(Vec3(-0.6 * std::cos(3 * x) * std::cos(2 * z), 1,
                                               0.4 * std::sin(3 * x) * std::sin(2 * z)));
        checkUnit(sp.shadingNormal);
        CHECK(glm::length(sp.shadingNormal - exact) < 2e-3);
        // The geometric normal stays the triangle's.
        CHECK(sp.normal != sp.shadingNormal);
    }
}
