#include "scene/instancing.hpp"

#include "scene/primitive_count.hpp"

namespace crt::scene {

namespace {

/// How often each entity is drawn through transforms, groups and unions. Parts come before
/// what is made of them: walking back, an entity's count is complete before it is handed down.
std::vector<uint64_t> usesOf(const SceneDesc& scene, const std::vector<bool>& drawnAsParts) {
    std::vector<uint64_t> uses(scene.entities.size(), 0);
    for (int32_t root : scene.drawn) uses[static_cast<size_t>(root)] += 1;
    for (size_t i = scene.entities.size(); i-- > 0;) {
        if (uses[i] == 0 || !drawnAsParts[i]) continue;
        forEachDrawnPart(scene.entities[i].shape, [&](int32_t part) {
            const auto p = static_cast<size_t>(part);
            if (p < i) uses[p] = saturatingAdd(uses[p], uses[i]);
        });
    }
    return uses;
}

} // namespace

SceneStorage storageOf(const SceneDesc& scene) {
    SceneStorage s;
    const size_t count = scene.entities.size();
    s.expansion.reserve(count);
    // Which entities are drawn as their parts, noted in the one pass that reads every entity:
    // the passes below look at the others' counts only.
    std::vector<bool> drawnAsParts(count);
    for (size_t i = 0; i < count; ++i) {
        const EntityDesc& e = scene.entities[i];
        s.expansion.push_back(primitivesOf(e, s.expansion));
        drawnAsParts[i] = forEachDrawnPart(e.shape, [](int32_t) {});
    }
    s.uses = usesOf(scene, drawnAsParts);
    s.instanced.resize(count);
    for (size_t i = 0; i < count; ++i)
        s.instanced[i] = s.uses[i] >= kMinInstanceUses && s.expansion[i] >= kMinInstancePrimitives &&
                         !std::holds_alternative<TransformNode>(scene.entities[i].shape);
    // What one drawing of an entity stores besides the prototypes it reaches: an instance
    // (one primitive), or for an entity drawn as its parts, theirs, or all it expands to.
    std::vector<uint64_t> copies(count, 0), instances(count, 0);
    for (size_t i = 0; i < count; ++i) {
        if (s.instanced[i]) {
            instances[i] = 1;
            continue;
        }
        if (!drawnAsParts[i]) {
            copies[i] = s.expansion[i];
            continue;
        }
        forEachDrawnPart(scene.entities[i].shape, [&](int32_t part) {
            const auto p = static_cast<size_t>(part);
            copies[i] = saturatingAdd(copies[i], p < i ? copies[p] : 1);
            if (p < i) instances[i] = saturatingAdd(instances[i], instances[p]);
        });
    }
    // The prototypes: each stores all its entity expands to, once, where first reached.
    std::vector<bool> visited(count, false);
    std::vector<int32_t> pending;
    uint64_t stored = 0;
    s.storedAfter.reserve(scene.drawn.size());
    for (int32_t root : scene.drawn) {
        const auto r = static_cast<size_t>(root);
        s.copied = saturatingAdd(s.copied, copies[r]);
        s.instances = saturatingAdd(s.instances, instances[r]);
        stored = saturatingAdd(stored, saturatingAdd(copies[r], instances[r]));
        // A root neither instanced nor drawn as parts reaches no prototype.
        if (s.instanced[r] || drawnAsParts[r]) pending.push_back(root);
        while (!pending.empty()) {
            const auto e = static_cast<size_t>(pending.back());
            pending.pop_back();
            if (visited[e]) continue;
            visited[e] = true;
            if (s.instanced[e]) {
                stored = saturatingAdd(stored, s.expansion[e]);
                continue;
            }
            if (!drawnAsParts[e]) continue;
            forEachDrawnPart(scene.entities[e].shape, [&](int32_t part) {
                if (static_cast<size_t>(part) < e) pending.push_back(part);
            });
        }
        s.storedAfter.push_back(stored);
    }
    return s;
}

} // namespace crt::scene
