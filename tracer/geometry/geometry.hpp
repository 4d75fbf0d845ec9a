// Every primitive behind one type, and the queries the renderer runs on them.
#pragma once

#include "tracer/geometry/blob.hpp"
#include "tracer/geometry/box.hpp"
#include "tracer/geometry/cone.hpp"
#include "tracer/geometry/cylinder.hpp"
#include "tracer/geometry/disc.hpp"
#include "tracer/geometry/height_field.hpp"
#include "tracer/geometry/isosurface.hpp"
#include "tracer/geometry/lathe.hpp"
#include "tracer/geometry/mesh.hpp"
#include "tracer/geometry/out_of_line.hpp"
#include "tracer/geometry/plane.hpp"
#include "tracer/geometry/polygon.hpp"
#include "tracer/geometry/prism.hpp"
#include "tracer/geometry/quad.hpp"
#include "tracer/geometry/sor.hpp"
#include "tracer/geometry/sphere.hpp"
#include "tracer/geometry/sphere_sweep.hpp"
#include "tracer/geometry/superellipsoid.hpp"
#include "tracer/geometry/text.hpp"
#include "tracer/geometry/torus.hpp"
#include "tracer/geometry/triangle.hpp"

#include <cstddef>
#include <optional>
#include <type_traits>
#include <variant>

namespace crt::tracer {

/// Shapes up to a sphere's size are held in a Geometry itself, larger ones out of line: the
/// shapes scenes hold by the million (spheres, drawings of a mesh) then take a primitive of
/// 48 bytes, and the others one pointer chase more.
inline constexpr size_t kInlineShapeBytes = sizeof(SphereGeometry);

/// How a Geometry holds a shape of type T.
template <typename T>
using StoredShape = std::conditional_t<(sizeof(T) <= kInlineShapeBytes), T, OutOfLine<T>>;

/// One primitive in its object space. Ask for a shape with shapeIf<T> or holds<T>, which do
/// not depend on how it is held.
using Geometry =
    std::variant<StoredShape<SphereGeometry>, StoredShape<BoxGeometry>, StoredShape<PlaneGeometry>,
                 StoredShape<CylinderGeometry>, StoredShape<ConeGeometry>, StoredShape<TorusGeometry>,
                 StoredShape<DiscGeometry>, StoredShape<QuadGeometry>, StoredShape<TriangleGeometry>,
                 StoredShape<MeshGeometry>, StoredShape<SuperellipsoidGeometry>, StoredShape<PolygonGeometry>,
                 StoredShape<PrismGeometry>, StoredShape<SorGeometry>, StoredShape<LatheGeometry>,
                 StoredShape<TextGeometry>, StoredShape<BlobGeometry>, StoredShape<IsosurfaceGeometry>,
                 StoredShape<HeightFieldGeometry>, StoredShape<SphereSweepGeometry>>;

/// The shape a Geometry's alternative holds, however it is held.
template <typename T>
const T& shapeOf(const T& shape) {
    return shape;
}
template <typename T>
const T& shapeOf(const OutOfLine<T>& shape) {
    return *shape;
}

/// The geometry's shape if it is a T, else null.
template <typename T>
const T* shapeIf(const Geometry& geometry) {
    const auto* stored = std::get_if<StoredShape<T>>(&geometry);
    return stored ? &shapeOf(*stored) : nullptr;
}

template <typename T>
bool holds(const Geometry& geometry) {
    return std::holds_alternative<StoredShape<T>>(geometry);
}

/// The bytes the geometry holds beyond itself: its shape's, when that is out of line (not
/// what the shape keeps of its own, such as a prism's outline).
size_t outOfLineBytes(const Geometry& geometry);

/// Object-space bounds (Bounds3::everything() for a plane, empty for a degenerate shape).
Bounds3 geometryBounds(const Geometry& geometry);
/// Every crossing of the whole line, ascending, and whether it starts inside (see shape.hpp).
void crossLine(const Geometry& geometry, const Ray& ray, CrossingList& out);
/// The surface at one of the crossings crossLine reported for the same ray. Without `wantUv`
/// the shape may leave uv at (0, 0) (only textures read it, and some shapes need
/// trigonometry for it).
SurfacePoint surfaceAt(const Geometry& geometry, const Ray& ray, const Crossing& crossing, bool wantUv = true);
/// What spherical and cylindrical image mappings wrap around on this primitive.
MappingAxis mappingAxis(const Geometry& geometry);
/// The area of a shape whose points can be drawn uniformly by area (a sphere, a disc, a quad,
/// a triangle), else 0.
double sampledArea(const Geometry& geometry);
/// A point of such a shape, uniform by area for u uniform in [0, 1)².
AreaSample sampleArea(const Geometry& geometry, const Vec2& u);
/// Whether the primitive bounds a volume (usable in CSG).
bool isSolid(const Geometry& geometry);
/// Whether the primitive is a bounded convex solid (a line crosses it at most twice).
bool isBoundedConvex(const Geometry& geometry);
/// Whether the primitive's surface lies in one plane (a plane, a disc, a quad, a triangle).
bool isFlat(const Geometry& geometry);
/// Whether crossLine costs about as much as testing a ray against the primitive's bounds
/// (then testing the bounds first does not pay).
bool hasCheapCrossings(const Geometry& geometry);

/// The primitive of a plain shape; nullopt for CSG, transform and group nodes, for meshes
/// (MeshGeometry, once the file is read) and for height fields (HeightFieldGeometry, once
/// their heights are read).
/// `limits`: the work a primitive may do for one line (an isosurface's evaluations).
std::optional<Geometry> makeGeometry(const scene::Shape& shape, const scene::RenderLimits& limits = {});

/// Visits the crossings with tMin < t < tMax until the visitor returns false (then false):
/// crossLine's in order, or a search of the window alone where the primitive has one: an
/// isosurface's (whose search along the line is long), in order; a mesh's, in the order its
/// BVH meets them, so that a visitor that stops early spares the search of the rest.
/// `skippedPart`: a face the ray leaves from, which a mesh need not test (kNoPart: none).
bool crossingsIn(const Geometry& geometry, const Ray& ray, double tMin, double tMax, CrossingVisitor visit,
                 uint32_t skippedPart = kNoPart);
/// The first crossing with tMin < t < tMax, for nearest-hit queries: crossingsIn's first, or
/// a nearest-first search where the primitive has one (a mesh). `skippedPart` as above.
bool firstCrossingIn(const Geometry& geometry, const Ray& ray, double tMin, double tMax, Crossing& out,
                     uint32_t skippedPart = kNoPart);

} // namespace crt::tracer
