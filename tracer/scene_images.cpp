// Image loading through the OpenImageIO module.
#include "tracer/scene_images.hpp"

#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/image_io.hpp"

namespace crt::tracer {

namespace {

/// Reads `path` unless read already; a failure names where the script asked for the image.
bool load(const scene::SceneDesc& desc, const std::string& path, const scene::SourceSpan& usedAt,
          bool decodeSrgb, SceneImages& images, std::string& error) {
    if (path.empty() || images.byPath.count(path)) return true;
    bool eightBit = false;
    std::optional<image_io::ImageBuffer> buffer =
        image_io::readImage(path, error, &eightBit, desc.limits.maxImagePixels);
    if (!buffer) {
        const std::string where = scene::spanLocation(desc, usedAt);
        if (!where.empty()) error = where + ": error: " + error;
        return false;
    }
    Image image;
    image.width = buffer->width;
    image.height = buffer->height;
    if (buffer->channels == 4) {
        // Colour and coverage apart: the alpha is neither sRGB-decoded nor premultiplied.
        size_t pixels = buffer->pixels.size() / 4;
        image.rgb.resize(pixels * 3);
        image.alpha.resize(pixels);
        for (size_t i = 0; i < pixels; ++i) {
            for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = buffer->pixels[4 * i + c];
            image.alpha[i] = buffer->pixels[4 * i + 3];
        }
    } else {
        image.rgb = std::move(buffer->pixels);
    }
    if (eightBit && decodeSrgb)
        for (float& v : image.rgb) v = image_io::srgbToLinear(v);
    images.byPath.emplace(path, std::move(image));
    return true;
}

} // namespace

bool loadSceneImages(const scene::SceneDesc& desc, SceneImages& images, std::string& error) {
    bool decodeSrgb = desc.settings.gamma != 1.0 || desc.settings.srgb;
    if (desc.background.kind == scene::BackgroundKind::Image &&
        !load(desc, scene::fileToOpen(desc.background.resolvedImage, desc.background.image),
              desc.background.source, decodeSrgb, images, error))
        return false;
    for (const scene::TextureDesc& t : desc.textures) {
        if ((t.kind == scene::TextureKind::Image || t.kind == scene::TextureKind::ImageBump) &&
            !load(desc, scene::fileToOpen(t.resolvedFile, t.file), t.source,
                  decodeSrgb && t.kind == scene::TextureKind::Image, images, error))
            return false;
    }
    return true;
}

} // namespace crt::tracer
