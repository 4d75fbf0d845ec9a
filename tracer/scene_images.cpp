// Image loading through the OpenImageIO module.
#include "tracer/scene_images.hpp"

#include "tracer/image_io/encoding.hpp"
#include "tracer/image_io/image_io.hpp"

namespace crt::tracer {

namespace {

bool load(const std::string& path, bool decodeSrgb, SceneImages& images, std::string& error) {
    if (path.empty() || images.byPath.count(path)) return true;
    bool eightBit = false;
    std::optional<image_io::ImageBuffer> buffer = image_io::readImage(path, error, &eightBit);
    if (!buffer) return false;
    Image image;
    image.width = buffer->width;
    image.height = buffer->height;
    image.rgb = std::move(buffer->pixels);
    if (eightBit && decodeSrgb)
        for (float& v : image.rgb) v = image_io::srgbToLinear(v);
    images.byPath.emplace(path, std::move(image));
    return true;
}

} // namespace

bool loadSceneImages(const scene::SceneDesc& desc, SceneImages& images, std::string& error) {
    bool decodeSrgb = desc.settings.gamma != 1.0 || desc.settings.srgb;
    if (desc.background.kind == scene::BackgroundKind::Image &&
        !load(scene::fileToOpen(desc.background.resolvedImage, desc.background.image), decodeSrgb, images, error))
        return false;
    for (const scene::TextureDesc& t : desc.textures) {
        if ((t.kind == scene::TextureKind::Image || t.kind == scene::TextureKind::ImageBump) &&
            !load(scene::fileToOpen(t.resolvedFile, t.file), decodeSrgb && t.kind == scene::TextureKind::Image, images, error))
            return false;
    }
    return true;
}

} // namespace crt::tracer
