#include "scene/primitive_count.hpp"

#include "scene/entity_parts.hpp"

#include <algorithm>
#include <vector>

namespace crt::scene {

uint64_t primitivesOf(const EntityDesc& entity, std::span<const uint64_t> earlier) {
    const bool combines = std::holds_alternative<CsgNode>(entity.shape) ||
                          std::holds_alternative<TransformNode>(entity.shape) ||
                          std::holds_alternative<GroupNode>(entity.shape) ||
                          std::holds_alternative<InverseNode>(entity.shape);
    if (!combines) return 1;
    uint64_t count = 0;
    forEachPart(entity, [&](int32_t part) {
        // Parts come before the entities made of them; a description that breaks this
        // (not one the front end built) counts such a part as one.
        const size_t index = static_cast<size_t>(part);
        count = saturatingAdd(count, index < earlier.size() ? earlier[index] : 1);
    });
    return count;
}

} // namespace crt::scene
