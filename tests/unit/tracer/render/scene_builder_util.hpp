// Helpers that build small scene descriptions in code for the render-core tests.
#pragma once

#include "tracer/render_scene.hpp"
#include "scene/scene_desc.hpp"

#include <utility>

namespace crt::tracer::test {

/// Appends to a SceneDesc and returns entity indices, so tests read like scripts.
class SceneMaker {
public:
    scene::SceneDesc desc;

    /// A material given with its finish in one struct, as shading sees it.
    int32_t material(const ShadingMaterial& m) {
        desc.materials.push_back({m.color, desc.internFinish(m), {}});
        return static_cast<int32_t>(desc.materials.size() - 1);
    }
    /// `material` -1: none of its own (drawn with the default one unless a transform gives one).
    int32_t entity(scene::Shape shape, int32_t material = -1, bool solid = true) {
        scene::EntityDesc e;
        e.shape = std::move(shape);
        e.material = material;
        e.solid = solid;
        desc.entities.push_back(std::move(e));
        return static_cast<int32_t>(desc.entities.size() - 1);
    }
    int32_t sphere(glm::dvec3 center, double radius, int32_t m = -1) { return entity(scene::SphereShape{center, radius}, m); }
    int32_t box(glm::dvec3 a, glm::dvec3 b, int32_t m = -1) { return entity(scene::BoxShape{a, b}, m); }
    int32_t plane(glm::dvec3 normal, glm::dvec3 position, int32_t m = -1) { return entity(scene::PlaneShape{normal, position}, m); }
    int32_t csg(scene::CsgOp op, int32_t left, int32_t right) { return entity(scene::CsgNode{op, left, right}); }
    /// `material`: given to the parts of `child` that have none.
    int32_t transformed(int32_t child, std::vector<scene::Modifier> modifiers,
                        int32_t material = -1) {
        return entity(scene::TransformNode{child, std::move(modifiers)}, material);
    }
    void draw(int32_t e) { desc.drawn.push_back(e); }
    int32_t colored(double r, double g, double b) {
        ShadingMaterial m;
        m.color = scene::Color{r, g, b, 1};
        return material(m);
    }
};

inline scene::Modifier translate(glm::dvec3 v) { return {scene::ModifierKind::Translate, v}; }
inline scene::Modifier rotate(glm::dvec3 v) { return {scene::ModifierKind::Rotate, v}; }
inline scene::Modifier scale(glm::dvec3 v) { return {scene::ModifierKind::Scale, v}; }

} // namespace crt::tracer::test
