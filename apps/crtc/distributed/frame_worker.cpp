// A rank's side of an animation shared out by frames.
#include "frame_worker.hpp"

#include "frame_agreement.hpp"
#include "frame_hash.hpp"
#include "frame_message.hpp"
#include "tile_message.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// How long a worker sleeps when it waits for rank 0's answer.
constexpr auto kPollInterval = std::chrono::microseconds(1000);
/// How often a worker tracing a frame sends the tiles finished meanwhile and looks for rank 0
/// cancelling it: rank 0 needs the tiles only once the frame is complete, so rarely, to keep
/// the wake-ups few (the last tiles go at once, when the render ends).
constexpr auto kSendInterval = std::chrono::milliseconds(5);

/// unchangedFrameKey digested in 192 bits (two independent 64-bit hashes and the length), so
/// that ranks compare frames without sending their scenes.
void digestKey(const std::string& key, uint64_t digest[3]) {
    uint64_t fnv = 0xcbf29ce484222325ULL;
    for (const unsigned char byte : key) fnv = (fnv ^ byte) * 0x100000001b3ULL;
    digest[0] = fnv;
    digest[1] = std::hash<std::string>{}(key);
    digest[2] = key.size();
}

/// The part of the image rendered: --region or all of it (renderedRegion's rule; a region
/// outside the image is reported by rank 0, and nothing is traced here).
bool regionOf(const Options& options, const scene::SceneDesc& scene, tracer::Tile& region) {
    const int width = scene.settings.width, height = scene.settings.height;
    region = options.region.value_or(tracer::Tile{0, 0, width, height});
    return region.x1 <= width && region.y1 <= height;
}

} // namespace

void FrameWorker::run() {
    link_.send(kFrameRequestTag, nullptr, 0);
    for (;;) {
        const int frame = awaitFrame();
        if (frame < 0) break;
        // The next frame is asked for now, so that it is here when this one is done, whatever
        // rank 0 is doing then (writing a frame, most often).
        link_.send(kFrameRequestTag, nullptr, 0);
        work(frame);
    }
    link_.send(kIdleTag, nullptr, 0);
}

int FrameWorker::awaitFrame() {
    for (;;) {
        if (!answers_.empty()) {
            const int frame = answers_.front();
            answers_.pop_front();
            return frame;
        }
        int tag = 0;
        std::vector<char> message;
        if (link_.take(tag, message))
            unwanted(-1, tag, message); // keeps a frame; the rest is about finished frames
        else
            std::this_thread::sleep_for(kPollInterval);
    }
}

bool FrameWorker::unwanted(int frame, int tag, const std::vector<char>& message) {
    int values[2] = {-1, 1};
    if (!message.empty())
        std::memcpy(values, message.data(), std::min(message.size(), sizeof values));
    if (tag == kFrameTag) answers_.push_back(values[0]);
    return values[0] == frame && ((tag == kVerdictTag && values[1] == 0) || tag == kCancelTag);
}

void FrameWorker::work(int frame) {
    lang::Compilation c;
    std::string why;
    FrameFacts facts;
    facts.frame = frame;
    facts.ok = evaluateOnThisRank(rank_, compileFrame_, frame, c, why) ? 1 : 0;
    why = captured_.take() + why; // warnings too: rank 0 prints them with the frame
    tracer::Tile region;
    bool inside = false;
    if (facts.ok) {
        scene::SceneDesc& scene = *c.scene;
        applyCommandLine(options_, scene);
        facts.width = scene.settings.width;
        facts.height = scene.settings.height;
        facts.gamma = scene.settings.gamma;
        facts.srgb = scene.settings.srgb ? 1 : 0;
        inside = regionOf(options_, scene, region);
        facts.hash = frameHash(c, scene, options_, region);
        digestKey(unchangedFrameKey(scene), facts.keyDigest);
    }
    const std::vector<char> message = withText(facts, why);
    link_.send(kFactsTag, message.data(), message.size());
    // Traced at once, without waiting for rank 0's verdict: most frames are wanted, and rank 0
    // may be busy writing one. A frame reused or finished before is stopped when it says so.
    if (facts.ok)
        trace(frame, *c.scene, inside ? tracer::regionTiles(region) : std::vector<tracer::Tile>());
}

void FrameWorker::trace(int frame, const scene::SceneDesc& scene,
                        const std::vector<tracer::Tile>& tiles) {
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<std::vector<char>> outbox; // finished tiles not yet sent
    bool finished = false;
    std::atomic<bool> cancel{false};
    tracer::RenderOutcome outcome;
    outcome.ok = true;
    std::thread renderer([&] {
        tracer::RenderJob job = renderJob(options_);
        job.tiles = tiles;
        job.cancel = &cancel;
        job.onTileDone = [&](const tracer::TileResult& result) {
            std::vector<char> tile = encodeTile(result);
            std::lock_guard lock(mutex); // sent at the next poll: no wake-up per tile
            outbox.push_back(std::move(tile));
        };
        try {
            if (!tiles.empty()) outcome = tracer::render(scene, job);
        } catch (const std::exception& e) {
            outcome.ok = false;
            outcome.error = e.what();
        }
        std::lock_guard lock(mutex);
        finished = true;
        changed.notify_all();
    });
    // This thread sends the tiles (MPI from the main thread only), a batch every few
    // milliseconds, and listens to rank 0.
    for (bool last = false; !last;) {
        TileBatch batch(frame);
        {
            std::unique_lock lock(mutex);
            changed.wait_for(lock, kSendInterval, [&] { return finished; });
            for (; !outbox.empty(); outbox.pop_front()) batch.add(outbox.front());
            last = finished;
        }
        if (!batch.empty() && !cancel.load())
            link_.send(kFrameTileTag, batch.bytes().data(), batch.bytes().size());
        int tag = 0;
        std::vector<char> message;
        while (link_.take(tag, message))
            if (unwanted(frame, tag, message)) cancel.store(true);
    }
    renderer.join();
    if (!outcome.ok && !outcome.cancelled) {
        const std::vector<char> error = withText(int32_t{frame}, outcome.error);
        link_.send(kFrameErrorTag, error.data(), error.size());
    }
    FrameDone done = frameDoneOf(outcome);
    done.frame = frame;
    link_.send(kFrameDoneTag, &done, sizeof done);
}

} // namespace crt::crtc::distributed
