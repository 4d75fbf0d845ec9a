// The entities an entity is made of, for walks over the entity graph.
#pragma once

#include "scene/scene_desc.hpp"

#include <variant>

namespace crt::scene {

/// Calls `visit` on every entity index `entity` refers to: CSG operands, a transform's or an
/// inverse's child, a group's members (references into `entity`, writable when it is).
template <typename Entity, typename F> void forEachPart(Entity& entity, F&& visit) {
    if (auto* csg = std::get_if<CsgNode>(&entity.shape)) {
        visit(csg->left);
        visit(csg->right);
    } else if (auto* transform = std::get_if<TransformNode>(&entity.shape)) {
        visit(transform->child);
    } else if (auto* group = std::get_if<GroupNode>(&entity.shape)) {
        for (auto& member : group->members) visit(member);
    } else if (auto* inverse = std::get_if<InverseNode>(&entity.shape)) {
        visit(inverse->child);
    }
}

} // namespace crt::scene
