// Helpers that build small scene descriptions in code for the render-core tests.
#pragma once

#include "tracer/render_scene.hpp"
#include "tracer/scene_desc.hpp"

#include <utility>

namespace crt::tracer::test {

/// Appends to a SceneDesc and returns entity indices, so tests read like scripts.
class SceneMaker {
public:
    SceneDesc desc;

    /// A material given with its finish in one struct, as shading sees it.
    int32_t material(const ShadingMaterial& m) {
        desc.materials.push_back({m.color, desc.internFinish(m), {}});
        return static_cast<int32_t>(desc.materials.size() - 1);
    }
    int32_t entity(Shape shape, int32_t material = -1, bool solid = true) {
        EntityDesc e;
        e.shape = std::move(shape);
        bool composite = std::holds_alternative<CsgNode>(e.shape) || std::holds_alternative<TransformNode>(e.shape) ||
                         std::holds_alternative<GroupNode>(e.shape);
        e.material = composite ? -1 : (material >= 0 ? material : defaultMaterial());
        e.solid = solid;
        desc.entities.push_back(std::move(e));
        return static_cast<int32_t>(desc.entities.size() - 1);
    }
    int32_t sphere(glm::dvec3 center, double radius, int32_t m = -1) { return entity(SphereShape{center, radius}, m); }
    int32_t box(glm::dvec3 a, glm::dvec3 b, int32_t m = -1) { return entity(BoxShape{a, b}, m); }
    int32_t plane(glm::dvec3 normal, glm::dvec3 position, int32_t m = -1) { return entity(PlaneShape{normal, position}, m); }
    int32_t csg(CsgOp op, int32_t left, int32_t right) { return entity(CsgNode{op, left, right}); }
    int32_t transformed(int32_t child, std::vector<Modifier> modifiers) {
        return entity(TransformNode{child, std::move(modifiers)});
    }
    void draw(int32_t e) { desc.drawn.push_back(e); }
    int32_t colored(double r, double g, double b) {
        ShadingMaterial m;
        m.color = Color{r, g, b, 1};
        return material(m);
    }

private:
    int32_t defaultMaterial() {
        if (default_ < 0) default_ = material(ShadingMaterial{});
        return default_;
    }
    int32_t default_ = -1;
};

inline Modifier translate(glm::dvec3 v) { return {ModifierKind::Translate, v}; }
inline Modifier rotate(glm::dvec3 v) { return {ModifierKind::Rotate, v}; }
inline Modifier scale(glm::dvec3 v) { return {ModifierKind::Scale, v}; }

} // namespace crt::tracer::test
