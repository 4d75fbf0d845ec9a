// Material maps and layers resolve to shares of plain materials, as POV-Ray's texture maps
// and layered textures do: each share is shaded on its own and the results are added.
#include "tracer/material_mix.hpp"

#include "tracer/patterns/map_position.hpp"

#include <algorithm>

namespace crt::tracer {

MaterialMixer::MaterialMixer(const std::vector<ShadingMaterial>& materials,
                             const std::vector<scene::BlendDesc>& blends,
                             const std::vector<Texture>& textures)
    : materials_(materials), blends_(blends), textures_(textures) {
    plain_.reserve(materials.size());
    for (const ShadingMaterial& m : materials) {
        bool translucent = m.texture >= 0 ? textures[static_cast<size_t>(m.texture)].translucent()
                                          : m.color.a != 1;
        plain_.push_back(m.blend < 0 && !translucent);
    }
}

Vec3 MaterialMixer::resolve(int32_t index, const SurfaceInteraction& si, double weight,
                            std::vector<MaterialShare>& shares) const {
    const ShadingMaterial& m = materials_[static_cast<size_t>(index)];
    if (m.blend >= 0) {
        const scene::BlendDesc& blend = blends_[static_cast<size_t>(m.blend)];
        return blend.kind == scene::BlendKind::Map ? resolveMap(blend, si, weight, shares)
                                                   : resolveLayers(blend, si, weight, shares);
    }
    Vec4 color = colorAt(m, si);
    double coverage = std::clamp(color.a, 0.0, 1.0);
    Vec3 surface(color);
    if (coverage > 0) shares.push_back({index, weight * coverage, surface});
    if (coverage == 1) return Vec3(0.0);
    return weight * (1 - coverage) * (Vec3(1 - m.filter) + m.filter * surface);
}

Vec3 MaterialMixer::resolveMap(const scene::BlendDesc& blend, const SurfaceInteraction& si,
                               double weight, std::vector<MaterialShare>& shares) const {
    const Texture& pattern = textures_[static_cast<size_t>(blend.pattern)];
    double value = pattern.value(si.objectPoint, si.shadingNormal);
    if (pattern.isDiscrete()) {
        // Checker, Hexagon and Brick pick their entries by position, as they pick colours.
        size_t entry = std::min(static_cast<size_t>(value), blend.materials.size() - 1);
        return resolve(blend.materials[entry], si, weight, shares);
    }
    MapPosition at = mapPosition(blend.values, value);
    if (at.below == at.above) return resolve(blend.materials[at.below], si, weight, shares);
    return resolve(blend.materials[at.below], si, weight * (1 - at.fraction), shares) +
           resolve(blend.materials[at.above], si, weight * at.fraction, shares);
}

Vec3 MaterialMixer::resolveLayers(const scene::BlendDesc& blend, const SurfaceInteraction& si,
                                  double weight, std::vector<MaterialShare>& shares) const {
    // From the top down: each layer takes what its coverage holds of the light the layers
    // above leave, and light passes the surface only through every layer.
    double uncovered = weight;
    Vec3 passes(weight);
    for (auto layer = blend.materials.rbegin(); layer != blend.materials.rend(); ++layer) {
        size_t first = shares.size();
        passes *= resolve(*layer, si, 1, shares);
        double coverage = 0;
        for (size_t i = first; i < shares.size(); ++i) {
            coverage += shares[i].weight;
            shares[i].weight *= uncovered;
        }
        uncovered *= std::max(0.0, 1 - coverage);
        if (uncovered <= 0) return Vec3(0.0);
    }
    return passes;
}

} // namespace crt::tracer
