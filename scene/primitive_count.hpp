// How many primitives a scene description expands to, counted without expanding it.
//
// The renderer draws every use of a shared entity as its own copies: `g = g + g` repeated 25
// times is 26 entities but 2^25 primitives. Counting through the entity graph, in the order
// the entities were made (parts always come first), costs one step per reference, so a
// limit on the expansion can be checked before anything is expanded. A mesh is the exception:
// its triangles are stored once however often it is drawn, and each drawing is one primitive.
#pragma once

#include "scene/scene_desc.hpp"

#include <cstdint>
#include <limits>
#include <span>

namespace crt::scene {

/// a + b, or the largest uint64_t when the sum would not fit.
inline uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
    return a > kMax - b ? kMax : a + b;
}

/// The primitives `entity` of `scene` expands to, given those of the entities made before it
/// (`earlier[i]` for entity i): a shape or a mesh is one, CSG the sum of its operands, a
/// transform its child, a group the sum of its members. Saturates instead of overflowing.
uint64_t primitivesOf(const EntityDesc& entity, std::span<const uint64_t> earlier);

/// The primitives the drawn entities of `scene` expand to, each drawing counted.
uint64_t drawnPrimitives(const SceneDesc& scene);

} // namespace crt::scene
