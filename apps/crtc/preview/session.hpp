// The preview's session: evaluates the script (again when it changes on disk or another
// frame is asked for) and renders it pass by pass with the page's camera and quality,
// cancelling a render as soon as anything it depends on changes.
#pragma once

#include "options.hpp"
#include "preview/camera_writer.hpp"
#include "preview/file_watcher.hpp"
#include "preview/render_plan.hpp"
#include "preview/viewport.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace crt::crtc::preview {

/// A finished pass, encoded for the page.
struct FrameImage {
    uint64_t number = 0; ///< counts every image published, from 1
    int width = 0, height = 0;
    int pass = 1, passes = 1; ///< which of the passes of its render
    bool final = false;       ///< the last pass: nothing more comes until something changes
    /// A path-traced image at the scene's quality, refined pass after pass while the camera is
    /// still: the paths its pixels have taken, on average, and its estimated relative error.
    /// 0 for other images.
    double paths = 0, relativeError = 0;
    std::vector<std::uint8_t> png;
};

/// What the page can be told: an event name ("frame", "progress", "diagnostics", "camera")
/// and its data.
using Publish = std::function<void(const std::string& event, const nlohmann::json& data)>;

class Session {
public:
    Session(Options options, Publish publish);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    /// Starts evaluating and rendering, and watching the script's files.
    void start();

    /// The script or a file it reads changed: evaluate again.
    void reload();
    /// The camera the page sees: the page's own once it moved it, else the script's.
    scene::CameraDesc camera() const;
    /// Applies `change` to the camera; `interactive`: part of a drag, rendered quickly until
    /// the moves stop. Returns the new camera.
    scene::CameraDesc changeCamera(const std::function<scene::CameraDesc(scene::CameraDesc)>& change,
                                   bool interactive);
    /// Back to the script's camera.
    void resetCamera();
    void setQuality(const ViewQuality& quality);
    /// Evaluates frame `frame` (clamped to the --frames range).
    void setFrame(int frame);
    /// The latest image; null before the first.
    std::shared_ptr<const FrameImage> latestImage() const;
    /// Everything the page shows besides the image, as JSON (docs/preview.md).
    nlohmann::json state() const;
    /// The entity at (fx, fy), fractions of the image from its top left, as JSON.
    nlohmann::json pick(double fx, double fy) const;
    /// A side view of the scene (viewport.hpp) as PNG bytes; empty, with `error` set, before a
    /// good evaluation or when it cannot be rendered.
    std::vector<std::uint8_t> viewport(const Viewport& view, std::string& error) const;
    /// Writes the current camera into the script's Settings block (or says where to paste).
    CameraEdit writeCamera();

private:
    /// A snapshot of what to render, taken when the render loop starts on a change.
    struct Request {
        bool evaluate = false;
        bool interactive = false;
        int frame = 0;
        ViewQuality quality;
    };

    void run();
    /// Bumps the generation and cancels the render in flight; the caller holds mutex_.
    void changed();
    /// Evaluates the script; false when there is nothing new to render (errors, or stopped).
    bool evaluate(int frame);
    /// The scene to render now (script's scene, page's camera); false before a good evaluation.
    bool currentScene(scene::SceneDesc& out) const;
    /// Renders a pass and publishes its image; false if cancelled or failed. `final`: the last
    /// pass of a refinement (not a drag's quick image). `seconds` (optional): how long it took.
    bool renderPass(const scene::SceneDesc& scene, const RenderPass& pass, int index, int count, bool final,
                    double* seconds = nullptr);
    /// Makes `pixels` the image on the page, a pass of `pass`'s render (`image` its place among
    /// the passes and its paths) after `seconds`.
    void publishImage(const tracer::PixelBuffer& pixels, const scene::SceneDesc& base, const RenderPass& pass,
                      FrameImage image, double seconds);
    /// Waits until the camera has not moved for a moment; false if something else came first.
    bool waitForStillness(uint64_t generation);
    void publishDiagnostics(const std::vector<std::string>& diagnostics, bool errors);

    Options options_;
    Publish publish_;
    std::atomic<bool> cancel_{false};
    /// Set by an edit or another frame: the evaluation under way is of no use any more (a
    /// camera move cancels renders, not evaluations).
    std::atomic<bool> evaluationStale_{false};
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    uint64_t generation_ = 1;
    bool stopping_ = false;
    bool needsEvaluation_ = true;
    bool interactive_ = false;
    std::chrono::steady_clock::time_point lastMove_;
    int frame_ = 0;
    ViewQuality quality_;
    double dragFraction_ = kFirstDragFraction; ///< of the size, for a drag's frames (render loop only)
    std::optional<scene::SceneDesc> scene_;         ///< the last evaluation without errors
    std::optional<scene::CameraDesc> pageCamera_;   ///< once the page moved the camera
    std::vector<std::string> diagnostics_;
    bool errors_ = false;
    std::shared_ptr<const FrameImage> image_;
    uint64_t imageCount_ = 0;
    FileWatcher watcher_;
    std::thread thread_;
};

} // namespace crt::crtc::preview
