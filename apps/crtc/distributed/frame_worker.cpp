// A rank's side of an animation shared out by frames.
#include "frame_worker.hpp"

#include "frame_agreement.hpp"
#include "frame_hash.hpp"
#include "frame_message.hpp"
#include "tile_message.hpp"

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
    for (;;) {
        link_.send(kFrameRequestTag, nullptr, 0);
        const std::vector<char> answer = await(kFrameTag);
        int frame = -1;
        if (answer.size() == sizeof frame) std::memcpy(&frame, answer.data(), sizeof frame);
        if (frame < 0) return;
        work(frame);
    }
}

std::vector<char> FrameWorker::await(Tag wanted) {
    for (;;) {
        int tag = 0;
        std::vector<char> message;
        if (!link_.take(tag, message)) {
            std::this_thread::sleep_for(kPollInterval);
            continue;
        }
        if (tag == wanted) return message;
    }
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
    if (!facts.ok) return;
    const std::vector<char> verdict = await(kVerdictTag);
    int traceIt = 0;
    if (verdict.size() == sizeof traceIt) std::memcpy(&traceIt, verdict.data(), sizeof traceIt);
    if (!traceIt) return;
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
        tracer::RenderJob job;
        job.tiles = tiles;
        job.threads = options_.threads;
        job.cancel = &cancel;
        job.onTileDone = [&](const tracer::TileResult& result) {
            std::vector<char> message = encodeTile(result);
            std::lock_guard lock(mutex); // sent at the next poll: no wake-up per tile
            outbox.push_back(std::move(message));
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
    // This thread sends the tiles as they come (MPI from the main thread only) and listens
    // for rank 0 cancelling the frame.
    for (;;) {
        std::unique_lock lock(mutex);
        while (!outbox.empty()) {
            const std::vector<char> message = std::move(outbox.front());
            outbox.pop_front();
            lock.unlock();
            link_.send(kResultTag, message.data(), message.size());
            lock.lock();
        }
        if (finished) break;
        lock.unlock();
        int tag = 0, cancelled = -1;
        std::vector<char> message;
        if (link_.take(tag, message) && tag == kCancelTag && message.size() == sizeof cancelled) {
            std::memcpy(&cancelled, message.data(), sizeof cancelled);
            if (cancelled == frame) cancel.store(true);
        }
        lock.lock();
        changed.wait_for(lock, kSendInterval, [&] { return finished; });
    }
    renderer.join();
    if (!outcome.ok && !outcome.cancelled)
        link_.send(kErrorTag, outcome.error.data(), outcome.error.size());
    const FrameDone done = frameDoneOf(outcome);
    link_.send(kFrameDoneTag, &done, sizeof done);
}

} // namespace crt::crtc::distributed
