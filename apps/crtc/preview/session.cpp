// The preview's evaluate-and-render loop (see session.hpp).
#include "preview/session.hpp"

#include "diagnostic_printer.hpp"
#include "preview/camera_json.hpp"
#include "preview/entity_names.hpp"
#include "preview/png_encoder.hpp"
#include "tracer/image_io/encoding.hpp"
#include "tracer/pick.hpp"
#include "tracer/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace crt::crtc::preview {

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

/// How long the camera must rest after a drag's last move before the image is refined.
constexpr auto kStillness = std::chrono::milliseconds(150);
/// How often the files are polled.
constexpr auto kWatchInterval = std::chrono::milliseconds(20);
/// How often a pass in flight reports its progress.
constexpr auto kProgressInterval = std::chrono::milliseconds(100);

/// Whether two cameras show the same view (their source spans aside).
bool sameView(const scene::CameraDesc& a, const scene::CameraDesc& b) {
    return a.position == b.position && a.pointing == b.pointing && a.up == b.up && a.fov == b.fov &&
           a.roll == b.roll && a.aperture == b.aperture && a.focalDistance == b.focalDistance &&
           a.projection == b.projection;
}

/// A diagnostic as text for the page: control characters other than line breaks and tabs
/// dropped (the page shows it as text, never as markup).
std::string sanitized(std::string text) {
    std::erase_if(text, [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t'; });
    return text;
}

/// Every file the evaluation read: scripts, then images and meshes.
std::vector<std::string> filesRead(const lang::Compilation& c) {
    std::vector<std::string> files;
    for (uint32_t i = 0; i < c.sources.fileCount(); ++i) files.push_back(c.sources.file(i).path());
    if (!c.scene) return files;
    const scene::SceneDesc& scene = *c.scene;
    auto add = [&](const std::string& resolved) {
        if (!resolved.empty()) files.push_back(resolved);
    };
    for (const scene::TextureDesc& t : scene.textures) add(t.resolvedFile);
    add(scene.background.resolvedImage);
    for (const scene::EntityDesc& e : scene.entities)
        if (auto* mesh = std::get_if<scene::MeshShape>(&e.shape)) add(mesh->resolvedFile);
        else if (auto* field = std::get_if<scene::HeightFieldShape>(&e.shape)) add(field->desc->resolvedImage);
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
    return files;
}

int scaled(int size, double scale) { return std::max(1, static_cast<int>(std::lround(size * scale))); }

} // namespace

Session::Session(Options options, Publish publish)
    : options_(std::move(options)), publish_(std::move(publish)), watcher_(kWatchInterval, [this] { reload(); }) {
    // The page's frame slider runs over 0 .. N-1; frame k is the animation's frame first + k.
    options_.eval.frameCount = std::max(options_.frames.count, 1);
    options_.eval.firstFrame = options_.frames.first;
    options_.eval.clockStart = options_.frames.clockStart;
    options_.eval.clockEnd = options_.frames.clockEnd;
    // print() must not mix with the URL and messages on standard output.
    options_.eval.printOut = &std::cerr;
}

Session::~Session() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        cancel_.store(true);
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void Session::start() { thread_ = std::thread([this] { run(); }); }

void Session::changed() {
    ++generation_;
    cancel_.store(true);
    wake_.notify_all();
}

void Session::reload() {
    std::lock_guard lock(mutex_);
    needsEvaluation_ = true;
    evaluationStale_.store(true);
    interactive_ = false;
    changed();
}

scene::CameraDesc Session::camera() const {
    std::lock_guard lock(mutex_);
    return pageCamera_ ? *pageCamera_ : scene_ ? scene_->camera : scene::CameraDesc{};
}

scene::CameraDesc Session::changeCamera(const std::function<scene::CameraDesc(scene::CameraDesc)>& change,
                                        bool interactive) {
    std::lock_guard lock(mutex_);
    scene::CameraDesc current = pageCamera_ ? *pageCamera_ : scene_ ? scene_->camera : scene::CameraDesc{};
    pageCamera_ = change(current);
    interactive_ = interactive;
    lastMove_ = Clock::now();
    changed();
    return *pageCamera_;
}

void Session::resetCamera() {
    std::lock_guard lock(mutex_);
    pageCamera_.reset();
    interactive_ = false;
    changed();
}

void Session::setQuality(const ViewQuality& quality) {
    std::lock_guard lock(mutex_);
    quality_ = quality;
    interactive_ = false;
    changed();
}

void Session::setFrame(int frame) {
    std::lock_guard lock(mutex_);
    frame_ = std::clamp(frame, 0, std::max(options_.frames.count, 1) - 1);
    needsEvaluation_ = true;
    evaluationStale_.store(true);
    interactive_ = false;
    changed();
}

std::shared_ptr<const FrameImage> Session::latestImage() const {
    std::lock_guard lock(mutex_);
    return image_;
}

json Session::state() const {
    std::lock_guard lock(mutex_);
    const scene::CameraDesc camera = pageCamera_ ? *pageCamera_ : scene_ ? scene_->camera : scene::CameraDesc{};
    json state = {{"script", options_.script},
                  {"frames", std::max(options_.frames.count, 1)},
                  {"frame", frame_},
                  {"quality", {{"draft", quality_.draft}, {"scale", quality_.scale}}},
                  {"camera", cameraJson(camera)},
                  {"cameraMoved", pageCamera_.has_value()},
                  {"diagnostics", diagnostics_},
                  {"errors", errors_},
                  {"image", image_ ? image_->number : 0}};
    if (scene_) {
        state["width"] = scene_->settings.width;
        state["height"] = scene_->settings.height;
        state["time"] = scene_->time;
    }
    return state;
}

bool Session::currentScene(scene::SceneDesc& out) const {
    std::lock_guard lock(mutex_);
    if (!scene_) return false;
    out = *scene_;
    if (pageCamera_) out.camera = *pageCamera_;
    return true;
}

json Session::pick(double fx, double fy) const {
    scene::SceneDesc scene;
    if (!currentScene(scene)) return {{"hit", false}, {"message", "the script has not been evaluated yet"}};
    std::string error;
    const std::optional<tracer::PickResult> found =
        tracer::pick(scene, fx * scene.settings.width, fy * scene.settings.height, error);
    if (!found) return {{"hit", false}, {"message", error}};
    if (!found->hit) return {{"hit", false}, {"message", "nothing there: the background"}};
    const scene::EntityDesc& entity = scene.entities[static_cast<size_t>(found->entity)];
    json answer = {{"hit", true},
                   {"kind", entityKind(entity)},
                   {"location", spanLocation(scene, entity.source)},
                   {"point", {found->point.x, found->point.y, found->point.z}},
                   {"distance", found->distance}};
    if (found->material >= 0)
        answer["material"] =
            spanLocation(scene, scene.materials[static_cast<size_t>(found->material)].source);
    // The entity drawn, when the surface is part of something larger built elsewhere (a CSG,
    // a macro's group).
    const int32_t root = drawnRootOf(scene, found->entity);
    const std::string rootLocation =
        root >= 0 ? spanLocation(scene, scene.entities[static_cast<size_t>(root)].source) : "";
    if (!rootLocation.empty() && rootLocation != answer["location"])
        answer["drawn"] = {{"kind", entityKind(scene.entities[static_cast<size_t>(root)])}, {"location", rootLocation}};
    return answer;
}

std::vector<std::uint8_t> Session::viewport(const Viewport& view, std::string& error) const {
    scene::SceneDesc scene;
    if (!currentScene(scene)) {
        error = "the script has not been evaluated yet";
        return {};
    }
    const scene::SceneDesc seen = viewportScene(scene, view);
    tracer::PixelBuffer pixels(view.pixels, view.lines);
    tracer::RenderJob job;
    job.tiles = tracer::imageTiles(view.pixels, view.lines);
    job.samples = passBudget(RenderPass{1, true});
    job.threads = 1; // a small image, beside the main view's render
    job.onTileDone = [&](const tracer::TileResult& tile) { pixels.place(tile); };
    const tracer::RenderOutcome outcome = tracer::render(seen, job);
    if (!outcome.ok) {
        error = outcome.error;
        return {};
    }
    return encodePng(view.pixels, view.lines,
                     tracer::image_io::quantise8(pixels.pixels, scene.settings.gamma, scene.settings.srgb));
}

CameraEdit Session::writeCamera() {
    const scene::CameraDesc current = camera();
    std::optional<std::string> text = lang::readFile(options_.script);
    if (!text) return {false, "", "cannot read '" + options_.script + "'"};
    CameraEdit edit = placeCamera(options_.script, *text, current, options_.eval);
    std::string error;
    if (edit.ok && !replaceFile(options_.script, edit.text, error)) edit = {false, "", error};
    return edit;
}

void Session::publishDiagnostics(const std::vector<std::string>& diagnostics, bool errors) {
    publish_("diagnostics", {{"errors", errors}, {"diagnostics", diagnostics}});
}

bool Session::evaluate(int frame) {
    lang::EvalOptions eval = options_.eval;
    eval.frame = options_.frames.first + frame;
    // An edit while evaluating makes this evaluation useless: stop it early.
    eval.interrupt = [this] { return evaluationStale_.load(std::memory_order_relaxed); };
    std::optional<std::string> text = lang::readFile(options_.script);
    if (!text) {
        watcher_.watch({options_.script});
        std::vector<std::string> diagnostics{"crtc: cannot read '" + options_.script + "'"};
        {
            std::lock_guard lock(mutex_);
            diagnostics_ = diagnostics;
            errors_ = true;
        }
        publishDiagnostics(diagnostics, true);
        return false;
    }
    lang::Compilation c = lang::compile(options_.script, *text, eval);
    if (evaluationStale_.load()) return false; // the next round evaluates the new text
    watcher_.watch(filesRead(c));
    if (options_.werror) c.diagnostics.promoteWarnings();
    std::vector<std::string> diagnostics;
    for (const lang::Diagnostic& d : c.diagnostics.items())
        diagnostics.push_back(sanitized(lang::formatDiagnostic(c.sources, d)));
    const bool errors = c.diagnostics.hasErrors();
    {
        std::lock_guard lock(mutex_);
        if (c.scene && !errors) {
            if (options_.width > 0) c.scene->settings.width = options_.width;
            if (options_.height > 0) c.scene->settings.height = options_.height;
            // A camera changed in the script wins over the page's.
            if (scene_ && !sameView(scene_->camera, c.scene->camera)) pageCamera_.reset();
            scene_ = std::move(*c.scene);
        }
        diagnostics_ = diagnostics;
        errors_ = errors;
    }
    publishDiagnostics(diagnostics, errors);
    // A save between reading the script and watching it would go unseen: compare once more.
    if (lang::readFile(options_.script) != text) reload();
    return !errors;
}

bool Session::renderPass(const scene::SceneDesc& base, const RenderPass& pass, int index, int count,
                         bool final, double* seconds) {
    const scene::SceneDesc scene = passScene(base, pass);
    const int width = scene.settings.width, height = scene.settings.height;
    tracer::PixelBuffer pixels(width, height);
    tracer::RenderJob job;
    job.tiles = tracer::imageTiles(width, height);
    job.samples = passBudget(pass);
    job.threads = options_.threads;
    job.cancel = &cancel_;
    const int tiles = static_cast<int>(job.tiles.size());
    int done = 0;
    Clock::time_point lastProgress = Clock::now();
    job.onTileDone = [&](const tracer::TileResult& tile) {
        pixels.place(tile);
        ++done;
        if (Clock::now() - lastProgress < kProgressInterval) return;
        lastProgress = Clock::now();
        publish_("progress", {{"pass", index + 1}, {"passes", count}, {"done", done}, {"tiles", tiles}});
    };
    const Clock::time_point start = Clock::now();
    auto secondsSoFar = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    FrameImage frame;
    frame.pass = index + 1;
    frame.passes = count;
    // At the scene's quality a path-traced image is shown after each of its passes of paths.
    if (!pass.draft && scene.settings.integrator == scene::Integrator::Path) {
        job.progressive = tracer::ProgressiveRender{std::nullopt, [&](const tracer::PassImage& image) {
                                                        frame.paths = image.meanPaths;
                                                        frame.relativeError = image.relativeError;
                                                        publishImage(*image.image, base, pass, frame, secondsSoFar());
                                                    }};
    }
    const tracer::RenderOutcome outcome = tracer::render(scene, job);
    if (outcome.cancelled) return false;
    if (!outcome.ok) {
        std::vector<std::string> diagnostics{sanitized("crtc: " + outcome.error)};
        {
            std::lock_guard lock(mutex_);
            diagnostics_ = diagnostics;
            errors_ = true;
        }
        publishDiagnostics(diagnostics, true);
        return false;
    }
    const double took = secondsSoFar();
    if (seconds) *seconds = took;
    frame.final = final;
    publishImage(pixels, base, pass, frame, took);
    return true;
}

void Session::publishImage(const tracer::PixelBuffer& pixels, const scene::SceneDesc& base, const RenderPass& pass,
                           FrameImage frame, double seconds) {
    auto image = std::make_shared<FrameImage>(std::move(frame));
    image->width = pixels.width;
    image->height = pixels.height;
    image->png = encodePng(pixels.width, pixels.height,
                           tracer::image_io::quantise8(pixels.pixels, base.settings.gamma, base.settings.srgb));
    ViewQuality quality;
    {
        std::lock_guard lock(mutex_);
        image->number = ++imageCount_;
        image_ = image;
        quality = quality_;
    }
    nlohmann::json data{{"number", image->number},
                        {"width", image->width},
                        {"height", image->height},
                        {"displayWidth", scaled(base.settings.width, quality.scale)},
                        {"displayHeight", scaled(base.settings.height, quality.scale)},
                        {"pass", image->pass},
                        {"passes", image->passes},
                        {"draft", pass.draft},
                        {"final", image->final},
                        {"seconds", seconds}};
    if (image->paths > 0) {
        data["paths"] = image->paths;
        data["relativeError"] = image->relativeError;
    }
    publish_("frame", data);
}

bool Session::waitForStillness(uint64_t generation) {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (stopping_ || generation_ != generation) return false;
        const Clock::time_point due = lastMove_ + kStillness;
        if (Clock::now() >= due) return true;
        wake_.wait_until(lock, due);
    }
}

void Session::run() {
    uint64_t seen = 0;
    for (;;) {
        Request request;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            cancel_.store(false);
            request = {needsEvaluation_, interactive_, frame_, quality_};
            if (needsEvaluation_) evaluationStale_.store(false);
            needsEvaluation_ = false;
        }
        // A script with errors leaves the last good image on screen as it is.
        if (request.evaluate && !evaluate(request.frame)) continue;
        scene::SceneDesc scene;
        if (!currentScene(scene)) continue;
        std::vector<RenderPass> passes = refinementPasses(request.quality);
        if (request.interactive) {
            const RenderPass quick = interactivePass(request.quality, dragFraction_);
            double seconds = 0;
            if (!renderPass(scene, quick, 0, 1, false, &seconds)) continue;
            dragFraction_ = nextDragFraction(dragFraction_, seconds);
            if (!waitForStillness(seen)) continue;
            // The drag's image stands in for the coarser passes.
            std::erase_if(passes, [&](const RenderPass& p) { return p.draft && p.scale <= quick.scale; });
        }
        const int count = static_cast<int>(passes.size());
        for (int i = 0; i < count; ++i)
            if (!renderPass(scene, passes[static_cast<size_t>(i)], i, count, i + 1 == count)) break;
    }
}

} // namespace crt::crtc::preview
