// How many primitives an entity expands to, counted without expanding it.
//
// `g = g + g` repeated 25 times is 26 entities but 2^25 primitives. Counting through the
// entity graph, in the order the entities were made (parts always come first), costs one step
// per reference, so what a scene stores (scene/instancing.hpp) can be checked against a limit
// before anything is expanded. A mesh counts one: its triangles are stored once however often
// it is drawn.
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

} // namespace crt::scene
