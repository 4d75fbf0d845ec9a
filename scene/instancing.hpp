// Which entities the renderer stores once and draws as instances, and so how many primitives
// a scene stores: decided from the description alone, so that the front end's limit and the
// renderer count the same.
//
// An entity of kMinInstancePrimitives primitives or more drawn kMinInstanceUses times or
// more through transforms, groups and unions (a transform itself excepted: its child is what
// repeats) is stored once, as a prototype, and each drawing is one primitive (an instance).
// Instances are one level deep: a prototype holds copies of everything it is made of. Other
// entities are stored as copies, each drawing all it expands to. A mesh drawing is one
// primitive; its triangles, stored once, are counted where they are read.
#pragma once

#include "scene/scene_desc.hpp"

#include <cstdint>
#include <variant>
#include <vector>

namespace crt::scene {

/// Below these a copy costs about as much memory as an instance does, and a ray reaches it
/// through one BVH less.
inline constexpr uint64_t kMinInstanceUses = 2;
inline constexpr uint64_t kMinInstancePrimitives = 16;

/// Calls f(part) for each part the shape is drawn as (a transform's child, a group's members,
/// a union's operands); false for a shape drawn as itself (a primitive, other CSG).
template <typename F>
bool forEachDrawnPart(const Shape& shape, F&& f) {
    if (auto* t = std::get_if<TransformNode>(&shape)) {
        f(t->child);
    } else if (auto* g = std::get_if<GroupNode>(&shape)) {
        for (int32_t m : g->members) f(m);
    } else if (auto* c = std::get_if<CsgNode>(&shape); c && c->op == CsgOp::Union) {
        f(c->left);
        f(c->right);
    } else {
        return false;
    }
    return true;
}

/// How the renderer stores a scene (all counts saturate instead of overflowing).
struct SceneStorage {
    std::vector<uint64_t> expansion; ///< per entity: the primitives it expands to
    std::vector<uint64_t> uses;      ///< per entity: how often it is drawn
    std::vector<bool> instanced;     ///< per entity: stored once, each drawing an instance
    /// Per drawn root (in the order of SceneDesc::drawn): the primitives stored once it and
    /// those before it are drawn (a prototype counts where it is first reached).
    std::vector<uint64_t> storedAfter;

    /// Of those, the primitives stored as copies outside every prototype, and the instances.
    uint64_t copied = 0, instances = 0;

    /// The primitives the whole scene stores (mesh triangles aside).
    uint64_t stored() const { return storedAfter.empty() ? 0 : storedAfter.back(); }
};

SceneStorage storageOf(const SceneDesc& scene);

} // namespace crt::scene
