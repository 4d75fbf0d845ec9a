// The height field primitive: POV-Ray's, a grid of heights over the unit square, two
// triangles a cell, closed below into a solid.
#pragma once

#include "tracer/geometry/box.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// Heights in [0, 1] at columns × rows points: point (i, j) is at x = i / (columns − 1),
/// z = j / (rows − 1). With smooth shading, a unit normal at each point too.
struct HeightGrid {
    int columns = 0, rows = 0;
    std::vector<float> heights; ///< row after row, from z = 0
    std::vector<glm::vec3> normals; ///< empty unless smooth

    float at(int i, int j) const { return heights[static_cast<size_t>(j) * columns + i]; }
    /// Fills `normals` as POV-Ray's smooth height field has them: each point's the sum of the
    /// unit normals of the four right triangles it makes with its neighbours along x and z,
    /// measured in cells and 65536ths of the height.
    void computeNormals();
};

/// The surface y = h(x, z) over the unit square of the x-z plane, h interpolated linearly on
/// the two triangles of each cell (the diagonal from (i + 1, j) to (i, j + 1), as POV-Ray
/// has it), and the solid between it and y = 0: walls at the square's edges and a bottom
/// close it. Along a line, the height above the surface is linear between the points where
/// the line passes a cell's edge or diagonal; it is evaluated once at each, so that a sign
/// change between two is one crossing, wherever it lies. Part 0 is the surface; 1 + k is
/// face k of the box holding the solid (BoxGeometry's parts).
class HeightFieldGeometry {
  public:
    HeightFieldGeometry(std::shared_ptr<const HeightGrid> grid, bool smooth);

    Bounds3 bounds() const { return box_.bounds(); }
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return true; }
    MappingAxis mappingAxis() const { return {Vec3(0.5, 0, 0.5), Vec3(0, 1, 0)}; }

    /// The surface's height at (x, z) of the square.
    double heightAt(double x, double z) const;

  private:
    struct Cell {
        int i, j;
        double fx, fz; ///< where in the cell, 0 to 1
    };
    Cell cellAt(double x, double z) const;
    /// The height of the line at t over the surface there.
    double clearance(const Ray& ray, double t) const;

    std::shared_ptr<const HeightGrid> grid_;
    bool smooth_;
    BoxGeometry box_;
};

} // namespace crt::tracer
