// The defaults that differ by texture kind (the others are TextureDesc's own).
#include "scene/scene_desc.hpp"

namespace crt::scene {

TextureDesc defaultTexture(TextureKind kind) {
    TextureDesc t;
    t.kind = kind;
    // The patterns new beside 2015's read black to white, as POV-Ray's do without a map.
    if (kind > TextureKind::ImageBump) t.colors = {{0, {0, 0, 0, 1}}, {1, {1, 1, 1, 1}}};
    switch (kind) {
    case TextureKind::Noise:
    case TextureKind::Marble:
    // Their octaves are their own noise's layers, 4 as in 2015.
    case TextureKind::NoiseBump: t.octaves = 4; break;
    // Wood's rings wander less than Marble's veins.
    case TextureKind::Wood: t.turbulence = 0.1; break;
    // POV-Ray's colours for the patterns that pick colours by position.
    case TextureKind::Brick: t.colors = {{0, {0.5, 0.5, 0.5, 1}}, {1, {0.6, 0.15, 0.15, 1}}}; break;
    case TextureKind::Hexagon:
        t.colors = {{0, {0, 0, 1, 1}}, {0.5, {0, 1, 0, 1}}, {1, {1, 0, 0, 1}}};
        break;
    case TextureKind::Spiral: t.waveform = Waveform::Triangle; break;
    // Up: 1 on tops, 0 underneath.
    case TextureKind::Slope: t.axis = {0, 1, 0}; break;
    default: break;
    }
    return t;
}

} // namespace crt::scene
