// Every primitive behind one type, and the queries the renderer runs on them.
#include "tracer/geometry/geometry.hpp"

#include <type_traits>

namespace crt::tracer {

Bounds3 geometryBounds(const Geometry& geometry) {
    return std::visit([](const auto& g) { return shapeOf(g).bounds(); }, geometry);
}

void crossLine(const Geometry& geometry, const Ray& ray, CrossingList& out) {
    std::visit([&](const auto& g) { shapeOf(g).crossLine(ray, out); }, geometry);
}

SurfacePoint surfaceAt(const Geometry& geometry, const Ray& ray, const Crossing& crossing, bool wantUv) {
    return std::visit([&](const auto& g) { return shapeOf(g).surfaceAt(ray, crossing, wantUv); }, geometry);
}

MappingAxis mappingAxis(const Geometry& geometry) {
    return std::visit(
        [](const auto& stored) {
            const auto& g = shapeOf(stored);
            if constexpr (requires { g.mappingAxis(); })
                return g.mappingAxis();
            else
                return MappingAxis{};
        },
        geometry);
}

double sampledArea(const Geometry& geometry) {
    return std::visit(
        [](const auto& stored) {
            const auto& g = shapeOf(stored);
            if constexpr (requires { g.sampleArea(Vec2(0.0)); })
                return g.area();
            else
                return 0.0;
        },
        geometry);
}

AreaSample sampleArea(const Geometry& geometry, const Vec2& u) {
    return std::visit(
        [&](const auto& stored) {
            const auto& g = shapeOf(stored);
            if constexpr (requires { g.sampleArea(u); })
                return g.sampleArea(u);
            else
                return AreaSample{};
        },
        geometry);
}

bool isSolid(const Geometry& geometry) {
    return std::visit([](const auto& g) { return shapeOf(g).solid(); }, geometry);
}

size_t outOfLineBytes(const Geometry& geometry) {
    return std::visit(
        [](const auto& stored) {
            using Shape = std::decay_t<decltype(shapeOf(stored))>;
            return std::is_same_v<std::decay_t<decltype(stored)>, Shape> ? size_t(0) : sizeof(Shape);
        },
        geometry);
}

bool isBoundedConvex(const Geometry& geometry) {
    if (holds<SphereGeometry>(geometry) || holds<BoxGeometry>(geometry)) return true;
    if (auto* c = shapeIf<CylinderGeometry>(geometry)) return c->solid();
    if (auto* c = shapeIf<ConeGeometry>(geometry)) return c->solid();
    if (auto* s = shapeIf<SuperellipsoidGeometry>(geometry)) return s->convex();
    return false;
}

bool isFlat(const Geometry& geometry) {
    return holds<PlaneGeometry>(geometry) ||
           holds<DiscGeometry>(geometry) ||
           holds<QuadGeometry>(geometry) ||
           holds<TriangleGeometry>(geometry) ||
           holds<PolygonGeometry>(geometry);
}

bool hasCheapCrossings(const Geometry& geometry) {
    return holds<SphereGeometry>(geometry) || holds<BoxGeometry>(geometry) ||
           holds<PlaneGeometry>(geometry) || holds<DiscGeometry>(geometry) ||
           holds<QuadGeometry>(geometry) || holds<TriangleGeometry>(geometry);
}

std::optional<Geometry> makeGeometry(const scene::Shape& shape, const scene::RenderLimits& limits) {
    return std::visit(
        [&](const auto& s) -> std::optional<Geometry> {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, scene::SphereShape>)
                return Geometry(SphereGeometry(s));
            else if constexpr (std::is_same_v<S, scene::BoxShape>)
                return Geometry(BoxGeometry(s));
            else if constexpr (std::is_same_v<S, scene::PlaneShape>)
                return Geometry(PlaneGeometry(s));
            else if constexpr (std::is_same_v<S, scene::CylinderShape>)
                return Geometry(CylinderGeometry(s));
            else if constexpr (std::is_same_v<S, scene::ConeShape>)
                return Geometry(ConeGeometry(s));
            else if constexpr (std::is_same_v<S, scene::TorusShape>)
                return Geometry(TorusGeometry(s));
            else if constexpr (std::is_same_v<S, scene::DiscShape>)
                return Geometry(DiscGeometry(s));
            else if constexpr (std::is_same_v<S, scene::QuadShape>)
                return Geometry(QuadGeometry(s));
            else if constexpr (std::is_same_v<S, scene::TriangleShape>)
                return Geometry(TriangleGeometry(s));
            else if constexpr (std::is_same_v<S, scene::PolygonShape>)
                return Geometry(PolygonGeometry(s));
            else if constexpr (std::is_same_v<S, scene::SmoothTriangleShape>)
                return s.mesh ? std::optional<Geometry>(MeshGeometry(std::make_shared<const TriangleMesh>(s.mesh)))
                              : std::nullopt;
            else if constexpr (std::is_same_v<S, scene::PrismShape>)
                return Geometry(PrismGeometry(s));
            else if constexpr (std::is_same_v<S, scene::SorShape>)
                return Geometry(SorGeometry(s));
            else if constexpr (std::is_same_v<S, scene::LatheShape>)
                return Geometry(LatheGeometry(s));
            else if constexpr (std::is_same_v<S, scene::SphereSweepShape>)
                return Geometry(SphereSweepGeometry(s));
            else if constexpr (std::is_same_v<S, scene::TextShape>)
                return Geometry(TextGeometry(s));
            else if constexpr (std::is_same_v<S, scene::BlobShape>)
                return Geometry(BlobGeometry(s));
            else if constexpr (std::is_same_v<S, scene::IsosurfaceShape>)
                return Geometry(IsosurfaceGeometry(s, limits.maxIsosurfaceEvaluations));
            else if constexpr (std::is_same_v<S, scene::SuperellipsoidShape>)
                return Geometry(SuperellipsoidGeometry(s));
            else
                return std::nullopt; // meshes, CSG, transforms, groups and inverses
        },
        shape);
}

bool crossingsIn(const Geometry& geometry, const Ray& ray, double tMin, double tMax, CrossingVisitor visit,
                 uint32_t skippedPart) {
    return std::visit(
        [&](const auto& stored) {
            const auto& g = shapeOf(stored);
            if constexpr (requires { g.crossingsIn(ray, tMin, tMax, visit, skippedPart); }) {
                return g.crossingsIn(ray, tMin, tMax, visit, skippedPart);
            } else if constexpr (requires { g.crossingsIn(ray, tMin, tMax, visit); }) {
                return g.crossingsIn(ray, tMin, tMax, visit);
            } else {
                CrossingList list;
                g.crossLine(ray, list);
                for (int i = 0; i < list.count; ++i)
                    if (list[i].t > tMin && list[i].t < tMax && !visit(list[i])) return false;
                return true;
            }
        },
        geometry);
}

bool firstCrossingIn(const Geometry& geometry, const Ray& ray, double tMin, double tMax, Crossing& out,
                     uint32_t skippedPart) {
    if (auto* mesh = shapeIf<MeshGeometry>(geometry))
        return mesh->firstCrossingIn(ray, tMin, tMax, out, skippedPart);
    bool found = false;
    auto first = [&](const Crossing& c) {
        out = c;
        found = true;
        return false;
    };
    crossingsIn(geometry, ray, tMin, tMax, first);
    return found;
}

} // namespace crt::tracer
