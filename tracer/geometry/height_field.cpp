// The height field primitive: POV-Ray's, a grid of heights over the unit square, two
// triangles a cell, closed below into a solid.
#include "tracer/geometry/height_field.hpp"

#include "tracer/geometry/geometry_math.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace crt::tracer {

void HeightGrid::computeNormals() {
    normals.assign(heights.size(), glm::vec3(0, 1, 0));
    // As POV-Ray, in the grid's own units (a cell a unit wide, heights in 65536ths), then
    // carried into the unit square as normals are (by the inverse transpose of the scaling).
    constexpr double kHeightUnits = 65536;
    auto point = [&](int i, int j) { return Vec3(i, at(i, j) * kHeightUnits, j); };
    const Vec3 toSquare(columns - 1, kHeightUnits, rows - 1);
    // The neighbours in turn around a point: +x, +z, −x, −z.
    constexpr int kAround[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const Vec3 p = point(i, j);
            Vec3 sum(0.0);
            for (int k = 0; k < 4; ++k) {
                const int ai = i + kAround[k][0], aj = j + kAround[k][1];
                const int bi = i + kAround[(k + 1) % 4][0], bj = j + kAround[(k + 1) % 4][1];
                if (ai < 0 || aj < 0 || bi < 0 || bj < 0 || ai >= columns || bi >= columns ||
                    aj >= rows || bj >= rows)
                    continue;
                Vec3 n = glm::normalize(glm::cross(point(bi, bj) - p, point(ai, aj) - p));
                sum += n.y < 0 ? -n : n;
            }
            normals[static_cast<size_t>(j) * columns + i] = glm::vec3(glm::normalize(glm::normalize(sum) * toSquare));
        }
    }
}

namespace {

float highest(const HeightGrid& grid) {
    return grid.heights.empty() ? 0.0f : *std::max_element(grid.heights.begin(), grid.heights.end());
}

/// The values of t, in order, where one coordinate of the line (in grid units) passes an
/// integer: g(t) = g0 + t·dg.
struct Boundaries {
    double g0 = 0, dg = 0;
    double k = 0; ///< the next integer passed

    Boundaries(double origin, double slope, double tStart) : g0(origin), dg(slope) {
        const double g = g0 + tStart * dg;
        k = dg > 0 ? std::floor(g) + 1 : std::ceil(g) - 1;
    }
    double next() const { return dg == 0 ? kInfinity : (k - g0) / dg; }
    void advance() { k += dg > 0 ? 1 : -1; }
};

} // namespace

HeightFieldGeometry::HeightFieldGeometry(std::shared_ptr<const HeightGrid> grid, bool smooth)
    : grid_(std::move(grid)), smooth_(smooth && !grid_->normals.empty()),
      box_(scene::BoxShape{glm::dvec3(0.0), glm::dvec3(1.0, highest(*grid_), 1.0)}) {}

HeightFieldGeometry::Cell HeightFieldGeometry::cellAt(double x, double z) const {
    const double gx = std::clamp(x, 0.0, 1.0) * (grid_->columns - 1);
    const double gz = std::clamp(z, 0.0, 1.0) * (grid_->rows - 1);
    const int i = std::min(static_cast<int>(gx), grid_->columns - 2);
    const int j = std::min(static_cast<int>(gz), grid_->rows - 2);
    return {i, j, gx - i, gz - j};
}

double HeightFieldGeometry::heightAt(double x, double z) const {
    const Cell c = cellAt(x, z);
    const HeightGrid& g = *grid_;
    if (c.fx + c.fz <= 1) {
        const double h00 = g.at(c.i, c.j);
        return h00 + (g.at(c.i + 1, c.j) - h00) * c.fx + (g.at(c.i, c.j + 1) - h00) * c.fz;
    }
    const double h11 = g.at(c.i + 1, c.j + 1);
    return h11 + (g.at(c.i, c.j + 1) - h11) * (1 - c.fx) + (g.at(c.i + 1, c.j) - h11) * (1 - c.fz);
}

double HeightFieldGeometry::clearance(const Ray& ray, double t) const {
    const Vec3 p = ray.at(t);
    return p.y - heightAt(p.x, p.z);
}

void HeightFieldGeometry::crossLine(const Ray& ray, CrossingList& out) const {
    CrossingList faces;
    box_.crossLine(ray, faces);
    if (faces.count < 2) return;
    const double tEnter = faces[0].t, tExit = faces[1].t;
    const double sx = grid_->columns - 1, sz = grid_->rows - 1;
    // Cell edges along x and z, and the diagonals, where gx + gz is a whole number.
    std::array<Boundaries, 3> lines{Boundaries(ray.origin.x * sx, ray.dir.x * sx, tEnter),
                                    Boundaries(ray.origin.z * sz, ray.dir.z * sz, tEnter),
                                    Boundaries(ray.origin.x * sx + ray.origin.z * sz,
                                               ray.dir.x * sx + ray.dir.z * sz, tEnter)};
    double tPrevious = tEnter;
    double cPrevious = clearance(ray, tEnter);
    if (cPrevious < 0) out.add(tEnter, 1 + faces[0].part);
    while (tPrevious < tExit) {
        int nearest = 0;
        for (int k = 1; k < 3; ++k)
            if (lines[k].next() < lines[nearest].next()) nearest = k;
        const double t = std::min(lines[nearest].next(), tExit);
        if (t > tPrevious) {
            const double c = clearance(ray, t);
            if ((c < 0) != (cPrevious < 0))
                out.add(tPrevious + (t - tPrevious) * (cPrevious / (cPrevious - c)), 0);
            tPrevious = t;
            cPrevious = c;
        }
        if (t < tExit) lines[nearest].advance();
        else break;
    }
    if (cPrevious < 0) out.add(tExit, 1 + faces[1].part);
}

SurfacePoint HeightFieldGeometry::surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv) const {
    if (crossing.part > 0) return box_.surfaceAt(ray, {crossing.t, crossing.part - 1}, wantUv);
    const Vec3 p = ray.at(crossing.t);
    const Cell c = cellAt(p.x, p.z);
    const HeightGrid& g = *grid_;
    const double h00 = g.at(c.i, c.j), h10 = g.at(c.i + 1, c.j);
    const double h01 = g.at(c.i, c.j + 1), h11 = g.at(c.i + 1, c.j + 1);
    // The slope of the cell's triangle, in heights per unit of x and z.
    const bool lower = c.fx + c.fz <= 1;
    const double slopeX = (lower ? h10 - h00 : h11 - h01) * (g.columns - 1);
    const double slopeZ = (lower ? h01 - h00 : h11 - h10) * (g.rows - 1);
    const Vec3 n = glm::normalize(Vec3(-slopeX, 1, -slopeZ));
    const double height = heightAt(p.x, p.z);
    const double error = errorGamma(8) * (std::abs(p.x) + std::abs(p.z) + std::abs(p.y) + height + 1);
    const RefinedPoint r = refineOntoSurface(p, (p.y - height) * n.y, error, n);
    SurfacePoint sp;
    sp.point = r.point;
    sp.pointError = r.error;
    sp.normal = sp.shadingNormal = n;
    if (smooth_) {
        auto normal = [&](int i, int j) { return Vec3(g.normals[static_cast<size_t>(j) * g.columns + i]); };
        const Vec3 blended = (1 - c.fz) * ((1 - c.fx) * normal(c.i, c.j) + c.fx * normal(c.i + 1, c.j)) +
                             c.fz * ((1 - c.fx) * normal(c.i, c.j + 1) + c.fx * normal(c.i + 1, c.j + 1));
        if (glm::length(blended) > 0) sp.shadingNormal = glm::normalize(blended);
    }
    if (wantUv) {
        sp.uv = Vec2(r.point.x, r.point.z);
        sp.dpdu = Vec3(1, slopeX, 0);
        sp.dpdv = Vec3(0, slopeZ, 1);
    }
    return sp;
}

} // namespace crt::tracer
