#include "tracer/solid_around.hpp"

#include <vector>

namespace crt::tracer {

bool fillsSolids(const RenderScene& scene, const MaterialMixer& mixer) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (mixer.isPlain(static_cast<int32_t>(i)) && fillsSolid(scene.materials[i])) return true;
    return false;
}

int32_t solidAround(const RenderScene& scene, const MaterialMixer& mixer, bool hides, const Vec3& point,
                    double time, QueryScratch& scratch, SolidAroundCache& cache) {
    if (point == cache.point && time == cache.time) return cache.material;
    // Along no axis or diagonal, in or along which the faces of boxes and grids lie.
    const Ray probe{point, glm::normalize(Vec3(0.5772, 0.5774, 0.5776)), time};
    struct First {
        int32_t material;
        double t;
        bool leaves;
    };
    std::vector<First> firsts; // each filling material's first crossing after the point
    RayStats uncounted;
    scene.forEachCrossing(probe, kInfinity, {}, scratch, uncounted, [&](const Hit& hit) {
        if (hides && (scene.hiddenFrom(hit) & scene::kHiddenFromCamera)) return true;
        const int32_t material = scene.materialOf(hit);
        if (material < 0 || !mixer.isPlain(material) || !fillsSolid(scene.materials[static_cast<size_t>(material)]))
            return true;
        const SurfaceInteraction si = scene.interaction(probe, hit);
        if (!si.solid) return true;
        const bool leaves = glm::dot(probe.dir, si.normal) > 0;
        for (First& f : firsts) {
            if (f.material != material) continue;
            if (hit.t < f.t) f = {material, hit.t, leaves};
            return true;
        }
        firsts.push_back({material, hit.t, leaves});
        return true;
    });
    int32_t around = -1;
    double nearest = kInfinity;
    for (const First& f : firsts) {
        if (f.leaves && f.t < nearest) {
            nearest = f.t;
            around = f.material;
        }
    }
    cache = {point, time, around};
    return around;
}

} // namespace crt::tracer
