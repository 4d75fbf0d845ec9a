// The entity under one image point (see pick.hpp).
#include "tracer/pick.hpp"

#include "tracer/camera.hpp"
#include "tracer/render_scene.hpp"

namespace crt::tracer {

std::optional<PickResult> pick(const scene::SceneDesc& scene, double x, double y, std::string& error) {
    std::unique_ptr<RenderScene> geometry = buildRenderScene(scene, error);
    if (!geometry) return std::nullopt;
    const Camera camera(scene.camera, scene.settings.width, scene.settings.height, 1);
    const Ray ray = camera.ray(x, y);
    Hit hit;
    QueryScratch scratch;
    RayStats stats;
    PickResult result;
    // What the camera sees: not what is hidden from it.
    Ray seen = ray;
    double skipped = 0;
    if (!geometry->intersectUnhidden(seen, scene::kHiddenFromCamera, hit, skipped, scratch, stats)) return result;
    result.hit = true;
    result.entity = geometry->entityOf(hit);
    // The render scene's materials are the description's, then the default.
    const int32_t material = geometry->materialOf(hit);
    if (static_cast<size_t>(material) < scene.materials.size()) result.material = material;
    result.distance = skipped + hit.t;
    result.point = ray.at(result.distance);
    return result;
}

} // namespace crt::tracer
