// What a surface point is made of: the plain materials of a MaterialMap or a Layered, each
// with its share, and the light that a colour's alpha lets through the surface unbent.
#pragma once

#include "tracer/render_scene.hpp"
#include "tracer/texture.hpp"

#include <vector>

namespace crt::tracer {

/// One plain material's part in a surface point.
struct MaterialShare {
    int32_t material = 0; ///< a material that is not made of others
    double weight = 0;    ///< of the light the point sends: its shading is scaled by this
    Vec3 color{0.0};      ///< its colour there
};

class MaterialMixer {
  public:
    /// Reads the three lists while it lives.
    MaterialMixer(const std::vector<ShadingMaterial>& materials,
                  const std::vector<scene::BlendDesc>& blends,
                  const std::vector<Texture>& textures);

    /// Whether material `index` is one opaque plain material: shading takes it as it is.
    bool isPlain(int32_t index) const { return plain_[static_cast<size_t>(index)] != 0; }
    /// A plain material's colour and alpha at the surface point.
    Vec4 colorAt(const ShadingMaterial& m, const SurfaceInteraction& si) const {
        if (m.texture < 0) return {m.color.r, m.color.g, m.color.b, m.color.a};
        return textures_[static_cast<size_t>(m.texture)].color(si.objectPoint, si.uv, si.shadingNormal, si.mappingAxis);
    }
    /// Appends to `shares` the plain materials material `index` is made of at the point, each
    /// weighted by `weight` times its part; returns `weight` times the light that passes the
    /// surface there unbent (what the alphas leave, tinted by `filter`).
    Vec3 resolve(int32_t index, const SurfaceInteraction& si, double weight,
                 std::vector<MaterialShare>& shares) const;

  private:
    Vec3 resolveMap(const scene::BlendDesc& blend, const SurfaceInteraction& si, double weight,
                    std::vector<MaterialShare>& shares) const;
    Vec3 resolveLayers(const scene::BlendDesc& blend, const SurfaceInteraction& si, double weight,
                       std::vector<MaterialShare>& shares) const;

    const std::vector<ShadingMaterial>& materials_;
    const std::vector<scene::BlendDesc>& blends_;
    const std::vector<Texture>& textures_;
    std::vector<uint8_t> plain_;
};

} // namespace crt::tracer
