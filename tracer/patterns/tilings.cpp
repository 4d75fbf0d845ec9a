// Patterns that tile space with cells of two or three colours.
#include "tracer/patterns/pattern_functions.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace crt::tracer::patterns {

namespace {

/// Which of a hexagon tiling's three colours a unit block of its 6 × 6 grid shows, where
/// the block is split by a hexagon's slanted edge (POV-Ray's hexagon pattern).
int slantedBlock(double xs, double zs, int xm, int zm) {
    double xl = xs - xm, zl = zs - zm;
    if ((xm + zm) % 2 == 1) xl = 1 - xl; // blocks whose edge falls: mirrored to rise
    if (xl == 0) xl = 0.0001;
    bool belowEdge = zl / xl < 1;
    switch (zm) {
    case 0:
    case 3: return belowEdge ? 0 : 2;
    case 2:
    case 5: return belowEdge ? 1 : 0;
    default: return belowEdge ? 2 : 1;
    }
}

} // namespace

double checker(const Vec3& p, double size) {
    // A tiny nudge keeps faces lying exactly on a cell boundary (z = 0 planes) on one colour.
    Vec3 q = p / size + Vec3(1e-9);
    long sum = static_cast<long>(std::floor(q.x)) + static_cast<long>(std::floor(q.y)) +
               static_cast<long>(std::floor(q.z));
    return static_cast<double>(sum & 1);
}

double stripes(const Vec3& p, const Vec3& axis, double size) {
    double along = glm::dot(p, glm::normalize(axis)) / size + 1e-9;
    return static_cast<double>(static_cast<long>(std::floor(along)) & 1);
}

double brick(const Vec3& p, const Vec3& brickSize, double mortar) {
    // POV-Ray's brick: courses along y, each half a brick along x and z from the last, and
    // joints `mortar` wide at the low side of each cell; its offsets keep the joints off 0.
    constexpr double kOffset = 1e-10;
    double joint = mortar - 2 * kOffset;
    Vec3 q = p + Vec3(kOffset + joint);
    if (fract(q.y / brickSize.y) <= joint / brickSize.y) return 0;
    bool oddCourse = fract(q.y / brickSize.y * 0.5) > 0.5;
    double shift = oddCourse ? 0.5 : 0;
    if (fract(q.x / brickSize.x + shift) <= joint / brickSize.x) return 0;
    if (fract(q.z / brickSize.z + (oddCourse ? 0 : 0.5)) <= joint / brickSize.z) return 0;
    return 1;
}

double hexagon(const Vec3& p) {
    // Hexagons in the x-z plane, their colours repeating over a 6 × 6 grid of half-width by
    // row-height blocks. z < 0 is shifted by six rows, not mirrored.
    constexpr double kHalfWidth = 0.5, kRowHeight = 0.866025404;
    double x = std::abs(p.x);
    double z = p.z < 0 ? 5.196152424 - std::abs(p.z) : p.z;
    double xs = x / kHalfWidth, zs = z / kRowHeight;
    xs -= std::floor(xs / 6) * 6;
    zs -= std::floor(zs / 6) * 6;
    int xm = static_cast<int>(std::floor(xs)) % 6, zm = static_cast<int>(std::floor(zs)) % 6;
    switch (xm) {
    case 0:
    case 5: return zm == 0 || zm == 5 ? 0 : zm <= 2 ? 1 : 2;
    case 2:
    case 3: return zm <= 1 ? 2 : zm <= 3 ? 0 : 1;
    default: return slantedBlock(xs, zs, xm, zm);
    }
}

} // namespace crt::tracer::patterns
