// A frame's identity for crtc --continue.
#include "frame_hash.hpp"

#include <fmt/format.h>

#include <cstring>
#include <sys/stat.h>

namespace crt::crtc {

namespace {

/// FNV-1a, 64 bits: no security needed, only that a changed input changes the hash.
class Hasher {
  public:
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 0x100000001b3ULL;
    }
    /// A string with its length, so that two strings cannot run into each other.
    void add(std::string_view text) {
        const uint64_t size = text.size();
        add(&size, sizeof size);
        add(text.data(), text.size());
    }
    /// A file's path, size and modification time, or that it is not there.
    void addFile(const std::string& path) {
        add(path);
        struct stat info {};
        if (stat(path.c_str(), &info) != 0) return add("missing");
        add(fmt::format("{} {}.{}", info.st_size, info.st_mtim.tv_sec, info.st_mtim.tv_nsec));
    }
    uint64_t value() const { return hash_; }

  private:
    uint64_t hash_ = 0xcbf29ce484222325ULL;
};

void addAssets(Hasher& h, const scene::SceneDesc& scene) {
    for (const scene::TextureDesc& texture : scene.textures)
        if (!texture.file.empty()) h.addFile(scene::fileToOpen(texture.resolvedFile, texture.file));
    if (!scene.background.image.empty())
        h.addFile(scene::fileToOpen(scene.background.resolvedImage, scene.background.image));
    for (const scene::EntityDesc& entity : scene.entities) {
        if (const auto* mesh = std::get_if<scene::MeshShape>(&entity.shape); mesh && mesh->written < 0)
            h.addFile(scene::fileToOpen(mesh->resolvedFile, mesh->file));
        if (const auto* field = std::get_if<scene::HeightFieldShape>(&entity.shape); field && !field->desc->image.empty())
            h.addFile(scene::fileToOpen(field->desc->resolvedImage, field->desc->image));
    }
}

} // namespace

uint64_t frameHash(const lang::Compilation& c, const scene::SceneDesc& scene,
                   const Options& options, const tracer::Tile& region) {
    Hasher h;
    h.add(CRT_VERSION);
    for (uint32_t i = 0; i < c.sources.fileCount(); ++i) {
        h.add(c.sources.file(i).path());
        h.add(c.sources.file(i).text());
    }
    const lang::EvalOptions& eval = options.eval;
    h.add(fmt::format("seed {} frame {} of {} from {} clock {}:{} time {}", eval.seed, scene.frame,
                      eval.frameCount, eval.firstFrame, eval.clockStart, eval.clockEnd,
                      scene.time));
    const scene::SettingsDesc& s = scene.settings;
    h.add(fmt::format("size {}x{} region {}:{}:{}:{} samples {} {} {} {} {} aperture {} alpha {} "
                      "integrator {} {} {} {} aovs {}",
                      s.width, s.height, region.x0, region.y0, region.x1, region.y1,
                      s.supersampling, static_cast<int>(s.antialias), s.dofSamples,
                      s.shadowSamples, s.glossySamples, scene.camera.aperture, options.alpha,
                      static_cast<int>(s.integrator), s.samples, s.bounces, s.targetError, options.aovs.bits));
    h.add(fmt::format("shutter {}:{} steps {}", s.shutterOpen, s.shutterClose, s.motionSteps));
    addAssets(h, scene);
    return h.value();
}

} // namespace crt::crtc
