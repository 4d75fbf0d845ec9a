// Rank 0's side of a shared render.
#include "tile_dispatcher.hpp"

#include "tile_message.hpp"

#include <fmt/format.h>

#include <chrono>
#include <exception>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// How long the main thread sleeps when no message waits: short beside a tile's tracing, long
/// enough that the polling takes no core from the render threads.
constexpr auto kPollInterval = std::chrono::microseconds(200);

} // namespace

std::vector<int> TileDispatcher::claim(int count) {
    std::lock_guard lock(mutex_);
    std::vector<int> tiles;
    if (!error_.empty() || (cancel_ && cancel_->load())) return tiles;
    while (count-- > 0 && next_ < tileCount_) tiles.push_back(next_++);
    return tiles;
}

void TileDispatcher::fail(std::string why) {
    std::lock_guard lock(mutex_);
    if (error_.empty()) error_ = std::move(why);
}

void TileDispatcher::deliver(const tracer::RenderJob& job, const tracer::TileResult& result) {
    std::lock_guard lock(deliverMutex_);
    if (job.onTileDone) job.onTileDone(result);
    ++delivered_;
}

void TileDispatcher::serveWorkers(const tracer::RenderJob& job,
                                  const std::atomic<bool>& localFinished) {
    const int workers = session_.size() - 1;
    int workersDone = 0;
    std::vector<float> pixels;
    const int channels = job.alpha ? 4 : 3;
    while (!localFinished.load() || workersDone < workers) {
        // Ctrl-C, or mpirun ending the job: no waiting for ranks that may be gone.
        if (job.cancel && job.cancel->load()) {
            drained_ = false;
            return;
        }
        int source = 0, tag = 0, bytes = 0;
        if (!session_.poll(source, tag, bytes)) {
            std::this_thread::sleep_for(kPollInterval);
            continue;
        }
        const std::vector<char> message = session_.receive(source, tag);
        if (tag == kRequestTag && message.size() == sizeof(int)) {
            int count = 0;
            std::memcpy(&count, message.data(), sizeof count);
            const std::vector<int> tiles = claim(count);
            session_.send(source, kTilesTag, tiles.data(), tiles.size() * sizeof(int));
        } else if (tag == kResultTag) {
            bool valid = true;
            const bool whole = TileBatch::split(message, [&](const std::vector<char>& tile) {
                int index = 0;
                valid = valid && decodeTile(tile, job.tiles, channels, pixels, index);
                if (valid)
                    deliver(job, tracer::TileResult{job.tiles[static_cast<size_t>(index)], index,
                                                    channels, pixels});
            });
            if (!whole || !valid)
                fail(fmt::format("{} sent a tile that is not one of the frame's",
                                 session_.describe(source)));
        } else if (tag == kErrorTag) {
            fail(fmt::format("{}: {}", session_.describe(source),
                             std::string(message.begin(), message.end())));
        } else if (tag == kDoneTag) {
            ++workersDone;
        }
    }
}

tracer::RenderOutcome TileDispatcher::render(const scene::SceneDesc& scene,
                                             const tracer::RenderJob& job) {
    Command command{Command::Render, 0, static_cast<int>(job.tiles.size()), 0};
    session_.broadcast(command);
    std::vector<int> corners = tileCorners(job.tiles);
    session_.broadcast(corners, static_cast<int>(corners.size()));
    tracer::RenderOutcome outcome;
    outcome.ok = true;
    if (job.tiles.empty()) return outcome; // every tile came from the resume log
    cancel_ = job.cancel;
    next_ = delivered_ = 0;
    tileCount_ = static_cast<int>(job.tiles.size());
    error_.clear();

    // Rank 0's threads take their tiles from the queue the other ranks are served from.
    tracer::RenderJob local = job;
    local.nextTile = [this] {
        const std::vector<int> tile = claim(1);
        return tile.empty() ? -1 : tile.front();
    };
    local.onTileDone = [&](const tracer::TileResult& result) { deliver(job, result); };
    std::atomic<bool> localFinished{false};
    std::thread renderer([&] {
        try {
            outcome = tracer::render(scene, local);
        } catch (const std::exception& e) {
            outcome.ok = false;
            outcome.error = e.what();
        }
        if (!outcome.ok && !outcome.cancelled) fail(outcome.error);
        localFinished.store(true);
    });
    serveWorkers(job, localFinished);
    renderer.join();
    if (!drained_) return outcome;
    outcome.stats = session_.sumStats(outcome.stats);
    outcome.tileCount = tileCount_;
    outcome.tilesDone = delivered_;
    outcome.error = error_;
    outcome.ok = error_.empty() && !outcome.cancelled && delivered_ == tileCount_;
    return outcome;
}

} // namespace crt::crtc::distributed
