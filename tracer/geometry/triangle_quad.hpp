// Up to four triangles of a mesh in single precision, tested against a line all at once to
// rule out those the line surely misses; the exact test (crossTriangle, in double) decides
// the others, so what a line crosses is what the exact test alone finds.
#pragma once

#include "tracer/bvh.hpp"

#include <cstdint>
#include <span>

namespace crt::tracer {

/// A mesh's single-precision frame: coordinates less a centre, all within `radius` of it on
/// every axis.
struct QuadFrame {
    Vec3 centre{0.0};
    double radius = 0;
};

/// A line in a QuadFrame, each value in all four lanes, with what bounds its rounding.
struct QuadRay {
    Float4 origin[3], dir[3];
    float dirSum;     ///< |dx| + |dy| + |dz|
    float inputError; ///< the most a corner less the origin, in float, is off on an axis

    QuadRay(const Ray& ray, const QuadFrame& frame);
};

/// Up to four triangles, triangle i in lane i: its first corner in the frame, and its two
/// edges from that corner (axis a of each in lanes: corner[a][i], edge[0][a][i]).
struct TriangleQuad {
    Float4 corner[3];
    Float4 edge[2][3];
    Int4 triangle; ///< the mesh's triangle in each lane; -1 where the quad has none

    /// Bit i set unless lane i holds no triangle or the line surely misses triangle i.
    int mayCross(const QuadRay& ray) const {
        // Möller and Trumbore's test: the line crosses the triangle where its three edge
        // functions (each barycentric weight times det) are all of one sign; crossTriangle's
        // edge functions are the same three, times one factor.
        Float4 toOrigin[3];
        for (int axis = 0; axis < 3; ++axis) toOrigin[axis] = ray.origin[axis] - corner[axis];
        Float4 p[3], q[3];
        cross(ray.dir, edge[1], p);
        cross(toOrigin, edge[0], q);
        const Float4 det = dot(edge[0], p);
        const Float4 u = dot(toOrigin, p);
        const Float4 v = dot(ray.dir, q);
        const Float4 w = det - u - v;
        // How far each may be off: the corner and the origin come rounded (by inputError on
        // each axis), the edges and the direction by a float rounding, and some ten roundings
        // follow, each relative to products of the edges, the direction and the distance to
        // the origin. Twice the sum of those bounds, and what results that underflow lose;
        // infinite where a size overflows, which rules nothing out.
        const Float4 reach = maxOf(absOf(toOrigin[0]), maxOf(absOf(toOrigin[1]), absOf(toOrigin[2])));
        const Float4 size0 = maxOf(absOf(edge[0][0]), maxOf(absOf(edge[0][1]), absOf(edge[0][2])));
        const Float4 size1 = maxOf(absOf(edge[1][0]), maxOf(absOf(edge[1][1]), absOf(edge[1][2])));
        const float e = ray.inputError;
        const Float4 margin =
            ray.dirSum * ((size0 + size1) * (kRoundings * 0x1p-24f * (reach + e) + 8 * e) + 128 * 0x1p-24f * size0 * size1) +
            kUnderflow;
        const Int4 negative = (u < -margin) | (v < -margin) | (w < -margin);
        const Int4 positive = (u > margin) | (v > margin) | (w > margin);
        return laneMask((triangle >= 0) & ~(negative & positive));
    }

    /// Float roundings (of 2⁻²⁴ each) of the distance to the origin in the margin.
    static constexpr float kRoundings = 96;
    /// Some ten times the most a result below the smallest normal float loses.
    static constexpr float kUnderflow = 0x1p-145f;

private:
    static Float4 absOf(Float4 x) { return x < 0 ? -x : x; }
    static Float4 maxOf(Float4 x, Float4 y) { return x > y ? x : y; }
    static void cross(const Float4 (&a)[3], const Float4 (&b)[3], Float4 (&out)[3]) {
        out[0] = a[1] * b[2] - a[2] * b[1];
        out[1] = a[2] * b[0] - a[0] * b[2];
        out[2] = a[0] * b[1] - a[1] * b[0];
    }
    static Float4 dot(const Float4 (&a)[3], const Float4 (&b)[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
};

/// The quad of triangles `triangles` (up to four), their corners p(triangle, k) in double.
template <typename Corner>
TriangleQuad makeTriangleQuad(const QuadFrame& frame, std::span<const int32_t> triangles, Corner&& p) {
    TriangleQuad quad;
    for (size_t lane = 0; lane < 4; ++lane) {
        const bool used = lane < triangles.size();
        quad.triangle[lane] = used ? triangles[lane] : -1;
        const Vec3 a = used ? p(triangles[lane], 0) : frame.centre;
        const Vec3 local = a - frame.centre;
        const Vec3 edge0 = used ? p(triangles[lane], 1) - a : Vec3(0.0);
        const Vec3 edge1 = used ? p(triangles[lane], 2) - a : Vec3(0.0);
        for (int axis = 0; axis < 3; ++axis) {
            quad.corner[axis][lane] = static_cast<float>(local[axis]);
            quad.edge[0][axis][lane] = static_cast<float>(edge0[axis]);
            quad.edge[1][axis][lane] = static_cast<float>(edge1[axis]);
        }
    }
    return quad;
}

} // namespace crt::tracer
