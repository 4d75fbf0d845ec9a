// Rank 0's side of a shared render.
#include "tile_dispatcher.hpp"

#include "tile_message.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <limits>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// How long the main thread sleeps when no message waits: short while rank 0's threads wait
/// for tiles given back, else long enough that the polling takes little from the render
/// threads (workers keep enough tiles queued not to wait for it).
constexpr auto kAnswerPoll = std::chrono::microseconds(200);
constexpr auto kIdlePoll = std::chrono::milliseconds(1);

/// The time a time-limited render has left, for the other ranks (whose clocks are their own).
int millisecondsLeft(std::chrono::steady_clock::time_point deadline) {
    const auto left = deadline - std::chrono::steady_clock::now();
    return static_cast<int>(std::clamp<int64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(left).count(), 0,
                                                std::numeric_limits<int>::max()));
}

} // namespace

bool TileDispatcher::stopped() const { return !error_.empty() || (cancel_ && cancel_->load()); }

std::vector<int> TileDispatcher::claim(int count) {
    std::vector<int> tiles;
    if (stopped()) return tiles;
    while (count > 0 && next_ < tileCount_) tiles.push_back(next_++), --count;
    // At the end, half of what another rank gave back: an idle worker shares it with rank 0's
    // threads rather than leave it all to them.
    for (count = std::min(count, static_cast<int>(returned_.size() + 1) / 2); count > 0; --count) {
        tiles.push_back(returned_.back());
        returned_.pop_back();
    }
    return tiles;
}

int TileDispatcher::claimLocal() {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (stopped()) return -1;
        if (!returned_.empty()) {
            const int tile = returned_.back();
            returned_.pop_back();
            return tile;
        }
        if (next_ < tileCount_) return next_++;
        const bool mayGiveBack = std::any_of(workers_.begin(), workers_.end(), [](const Worker& w) {
            return w.held > 0 && !w.allBegun;
        });
        if (!mayGiveBack) return -1;
        // The main thread asks the workers; the wait is bounded so that a Ctrl-C is seen.
        ++localWaiting_;
        givenBack_.wait_for(lock, kAnswerPoll);
        --localWaiting_;
    }
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

bool TileDispatcher::askForTilesBack() {
    std::vector<int> ask;
    {
        std::lock_guard lock(mutex_);
        if (localWaiting_ <= static_cast<int>(returned_.size())) return false;
        for (size_t rank = 1; rank < workers_.size(); ++rank) {
            Worker& w = workers_[rank];
            if (w.held > 0 && !w.allBegun && !w.askedBack && !w.doneSent) {
                w.askedBack = true;
                ask.push_back(static_cast<int>(rank));
            }
        }
    }
    for (const int rank : ask) session_.send(rank, kGiveBackTag, nullptr, 0);
    return true;
}

int TileDispatcher::releaseIfDone(int source) {
    Worker& w = workers_[static_cast<size_t>(source)];
    if (!w.doneSent || w.askedBack || w.released) return 0;
    w.released = true;
    session_.send(source, kReleaseTag, nullptr, 0);
    return 1;
}

int TileDispatcher::handle(const tracer::RenderJob& job, int source, int tag,
                           const std::vector<char>& message) {
    const int channels = job.channels();
    Worker& w = workers_[static_cast<size_t>(source)];
    if (tag == kRequestTag && message.size() == sizeof(int)) {
        std::vector<int> tiles;
        {
            std::lock_guard lock(mutex_);
            tiles = claim(intsOf(message).front());
            w.held += static_cast<int>(tiles.size());
            if (!tiles.empty()) w.allBegun = false;
        }
        session_.send(source, kTilesTag, tiles.data(), tiles.size() * sizeof(int));
    } else if (tag == kResultTag) {
        bool valid = true;
        int count = 0;
        std::vector<float> pixels;
        const bool whole = TileBatch::split(message, [&](const std::vector<char>& tile) {
            int index = 0;
            valid = valid && decodeTile(tile, job.tiles, channels, pixels, index);
            if (!valid) return;
            ++count;
            deliver(job, tracer::TileResult{job.tiles[static_cast<size_t>(index)], index, channels,
                                            pixels});
        });
        {
            std::lock_guard lock(mutex_);
            w.held -= count;
        }
        if (!whole || !valid)
            fail(fmt::format("{} sent a tile that is not one of the frame's", session_.describe(source)));
    } else if (tag == kGivenBackTag) {
        const std::vector<int> tiles = intsOf(message);
        {
            std::lock_guard lock(mutex_);
            for (const int tile : tiles)
                if (tile >= 0 && tile < tileCount_) returned_.push_back(tile);
            w.held -= static_cast<int>(tiles.size());
            w.allBegun = tiles.empty();
            w.askedBack = false;
        }
        givenBack_.notify_all();
        return releaseIfDone(source);
    } else if (tag == kErrorTag) {
        fail(fmt::format("{}: {}", session_.describe(source),
                         std::string(message.begin(), message.end())));
    } else if (tag == kDoneTag) {
        {
            std::lock_guard lock(mutex_);
            w.doneSent = true;
            w.held = 0;
        }
        givenBack_.notify_all();
        return releaseIfDone(source);
    }
    return 0;
}

void TileDispatcher::serveWorkers(const tracer::RenderJob& job,
                                  const std::atomic<bool>& localFinished) {
    const int workers = session_.size() - 1;
    int released = 0;
    while (!localFinished.load() || released < workers) {
        // Ctrl-C, or mpirun ending the job: no waiting for ranks that may be gone.
        if (job.cancel && job.cancel->load()) {
            drained_ = false;
            return;
        }
        const bool threadsWait = askForTilesBack();
        int source = 0, tag = 0, bytes = 0;
        if (!session_.poll(source, tag, bytes)) {
            std::this_thread::sleep_for(threadsWait ? kAnswerPoll : kIdlePoll);
            continue;
        }
        const std::vector<char> message = session_.receive(source, tag);
        released += handle(job, source, tag, message);
    }
}

tracer::RenderOutcome TileDispatcher::render(const scene::SceneDesc& scene,
                                             const tracer::RenderJob& job) {
    Command command{Command::Render, 0, static_cast<int>(job.tiles.size()), 0};
    session_.broadcast(command);
    std::vector<int> corners = tileCorners(job.tiles);
    session_.broadcast(corners, static_cast<int>(corners.size()));
    // A time-limited render (the only progressive one under mpirun).
    const bool timeLimited = job.progressive && job.progressive->deadline;
    if (timeLimited) {
        std::vector<int> left{millisecondsLeft(*job.progressive->deadline)};
        session_.broadcast(left, 1);
    }
    tracer::RenderOutcome outcome;
    outcome.ok = true;
    if (job.tiles.empty()) return outcome; // every tile came from the resume log
    cancel_ = job.cancel;
    tileCount_ = static_cast<int>(job.tiles.size());
    delivered_ = localWaiting_ = 0;
    next_ = timeLimited ? tileCount_ : 0; // no tile is handed out: each rank has its share
    returned_.clear();
    workers_.assign(static_cast<size_t>(session_.size()), Worker{});
    error_.clear();

    // Rank 0's threads take their tiles from the queue the other ranks are served from, or,
    // under a time limit, refine rank 0's share until the deadline.
    tracer::RenderJob local = job;
    std::vector<int> share;
    if (timeLimited) {
        share = timeLimitedShare(tileCount_, 0, session_.size());
        local.tiles.clear();
        for (const int t : share) local.tiles.push_back(job.tiles[static_cast<size_t>(t)]);
        local.onTileDone = [&](const tracer::TileResult& result) {
            deliver(job, {result.tile, share[static_cast<size_t>(result.index)], result.channels, result.pixels});
        };
    } else {
        local.nextTile = [this] { return claimLocal(); };
        local.onTileDone = [&](const tracer::TileResult& result) { deliver(job, result); };
    }
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
