// Scenes for the path integrator's render tests: a small image, grey Lambertian materials,
// and a floor seen from straight above.
#pragma once

#include "analytic_util.hpp"
#include "scene_builder_util.hpp"

namespace crt::tracer::test {

/// The side of the path tests' images, in pixels.
constexpr int kPathImageSize = 16;

inline scene::SceneDesc pathScene(const scene::CameraDesc& camera, int samples, int bounces) {
    scene::SceneDesc desc = blankScene(kPathImageSize, kPathImageSize, camera);
    desc.settings.integrator = scene::Integrator::Path;
    desc.settings.samples = samples;
    desc.settings.bounces = bounces;
    return desc;
}

/// A grey Lambertian material of `albedo`, glowing with `emission`.
inline ShadingMaterial diffuse(double albedo, double emission = 0) {
    ShadingMaterial m;
    m.color = scene::Color{albedo, albedo, albedo, 1};
    m.diffuse = 1;
    m.emission = scene::Color{emission, emission, emission, 1};
    return m;
}

/// The floor (a Lambertian plane of `albedo` at y = 0) filling the view from just above its
/// centre (a degree across), where the cases put their lights overhead.
inline SceneMaker floorSeenFromAbove(int samples, int bounces, double albedo) {
    SceneMaker m;
    scene::CameraDesc camera = lookAt({0, 1, 0}, {0, 0, 0}, 1);
    camera.up = {0, 0, 1};
    m.desc = pathScene(camera, samples, bounces);
    m.draw(m.plane({0, 1, 0}, {0, 0, 0}, m.material(diffuse(albedo))));
    return m;
}

/// A square area light of side `side` centred `height` above the origin, facing down.
inline scene::LightDesc areaLight(double side, double height, double color) {
    scene::LightDesc light;
    light.kind = scene::LightKind::Area;
    light.origin = {-side / 2, height, -side / 2};
    light.edgeA = {side, 0, 0};
    light.edgeB = {0, 0, side};
    light.color = scene::Color{color, color, color, 1};
    return light;
}

} // namespace crt::tracer::test
