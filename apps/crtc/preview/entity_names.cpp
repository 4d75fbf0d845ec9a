// Names of the scene's entities (see entity_names.hpp).
#include "preview/entity_names.hpp"

#include "scene/entity_parts.hpp"

#include <array>
#include <variant>

namespace crt::crtc::preview {

std::string entityKind(const scene::EntityDesc& entity) {
    // clang-format off
    static constexpr auto kNames = std::to_array<const char*>({
        "Sphere", "Box", "Plane", "Cylinder", "Cone", "Torus", "Disc", "Quad", "Triangle",
        "SmoothTriangle", "Polygon", "Superellipsoid", "Prism", "Sor", "Lathe", "SphereSweep", "Text",
        "Blob",
        "Isosurface", "HeightField", "Mesh", "CSG", "transformed entity", "group", "inverse"});
    // clang-format on
    static_assert(kNames.size() == std::variant_size_v<scene::Shape>,
                  "one name for each kind of shape, in the variant's order");
    if (auto* csg = std::get_if<scene::CsgNode>(&entity.shape)) {
        switch (csg->op) {
        case scene::CsgOp::Union: return "union";
        case scene::CsgOp::Difference: return "difference";
        case scene::CsgOp::Intersection: return "intersection";
        case scene::CsgOp::Merge: return "merge";
        case scene::CsgOp::Clip: return "clipped entity";
        }
    }
    return kNames[entity.shape.index()];
}

int32_t drawnRootOf(const scene::SceneDesc& scene, int32_t entity) {
    // Entities are shared, so the graph is a DAG: remember what was searched already.
    std::vector<bool> seen(scene.entities.size(), false);
    for (int32_t root : scene.drawn) {
        std::vector<int32_t> pending{root};
        while (!pending.empty()) {
            int32_t e = pending.back();
            pending.pop_back();
            if (e == entity) return root;
            if (e < 0 || seen[static_cast<size_t>(e)]) continue;
            seen[static_cast<size_t>(e)] = true;
            scene::forEachPart(scene.entities[static_cast<size_t>(e)], [&](int32_t part) { pending.push_back(part); });
        }
    }
    return -1;
}

} // namespace crt::crtc::preview
