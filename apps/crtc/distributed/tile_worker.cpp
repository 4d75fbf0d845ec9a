// The side of a shared render on the ranks other than 0.
#include "tile_worker.hpp"

#include "captured_errors.hpp"
#include "frame_agreement.hpp"
#include "frame_link.hpp"
#include "frame_worker.hpp"
#include "tile_message.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <iostream>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace crt::crtc::distributed {

namespace {

/// How often the main thread looks for rank 0's messages: often while it waits for tiles it
/// asked for, seldom otherwise (it is woken when the queue runs low), so that a worker's
/// polling takes little from its render threads.
constexpr auto kAnswerPoll = std::chrono::microseconds(200);
constexpr auto kIdlePoll = std::chrono::milliseconds(1);
/// The work a worker keeps queued per render thread, in seconds of tracing: enough that its
/// threads do not wait for rank 0's answer (a round trip of a few polling intervals, longer
/// on a loaded machine). The last tiles of a frame are still shared evenly: rank 0 takes back
/// what a worker has not begun when its own threads run out.
constexpr double kQueuedSeconds = 0.02;
/// The tiles a worker keeps queued per thread, at least and at most, whatever tiles cost.
constexpr int kQueuedMin = 2, kQueuedMax = 256;
/// How long finished tiles may wait before they are sent: batches of a few, not one message a
/// tile (tile_message.hpp says why).
constexpr auto kSendInterval = std::chrono::milliseconds(10);

/// One frame's tiles on a worker: the render threads trace what the main thread got from rank 0
/// and queue what they finish for the main thread to send.
class TileWorker {
  public:
    TileWorker(MpiSession& session, const Options& options)
        : session_(session),
          threads_(options.threads > 0 ? options.threads : static_cast<int>(tracer::availableCores())),
          options_(options) {
        if (const char* queued = std::getenv(kTestQueuedTilesVariable)) queuedForTests_ = std::atoi(queued);
    }

    /// Renders the tiles rank 0 hands out of `tiles` of `scene` (none if it was not evaluated),
    /// or with a `deadline` (a time-limited render) this rank's share of them, until then.
    void render(const scene::SceneDesc* scene, const std::vector<tracer::Tile>& tiles,
                std::optional<std::chrono::steady_clock::time_point> deadline);

  private:
    int nextTile();
    void finished(const tracer::TileResult& result);
    void exchange();
    /// Starts sending the finished tiles when they are due and the batch before has gone: a
    /// batch larger than OpenMPI sends at once waits for rank 0 to take it, and the main thread
    /// goes on meanwhile rather than wake every few hundred microseconds to see if it has.
    void sendResults();
    /// Asks rank 0 for more tiles once fewer than half the queue's target wait, so that no
    /// thread waits for the network; false once there is nothing more to ask.
    bool askIfLow();
    /// Rank 0's threads have run out: the last half of the tiles not begun go back to it.
    void giveBack();
    /// After kDoneTag: answers what rank 0 asked before it saw it, until it releases this rank.
    void awaitRelease();
    /// The tiles to keep queued: kQueuedSeconds of work at the pace tiles have been finished.
    int queueTarget() const;

    MpiSession& session_;
    const int threads_;
    const Options& options_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<int> queue_;                ///< tiles handed to this rank, not yet begun
    std::deque<std::vector<char>> outbox_; ///< finished tiles not yet sent
    std::optional<TileBatch> sending_;     ///< the batch on its way (kept until it has gone)
    bool asked_ = false, noMore_ = false, renderDone_ = false;
    std::chrono::steady_clock::time_point start_, lastSend_;
    int tilesDone_ = 0;
    int lowMark_ = 0; ///< fewer tiles queued than this: time to ask for more
    double secondsWaited_ = 0; ///< by the render threads, for tiles, all added up
    int queuedForTests_ = 0;   ///< kTestQueuedTilesVariable
};

int TileWorker::queueTarget() const {
    if (queuedForTests_ > 0) return queuedForTests_ * threads_;
    if (tilesDone_ == 0) return kQueuedMin * threads_;
    // The pace of tracing alone: counting the time threads waited for tiles would make a
    // starved worker ask for less, and starve it more.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double secondsPerTile = std::max(elapsed * threads_ - secondsWaited_, 0.0) / tilesDone_;
    const double perThread = std::ceil(kQueuedSeconds / std::max(secondsPerTile, 1e-6));
    return threads_ * static_cast<int>(std::clamp(perThread, double(kQueuedMin), double(kQueuedMax)));
}

int TileWorker::nextTile() {
    std::unique_lock lock(mutex_);
    const auto waitStart = std::chrono::steady_clock::now();
    changed_.wait(lock, [&] { return !queue_.empty() || noMore_; });
    secondsWaited_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - waitStart).count();
    if (queue_.empty()) return -1;
    const int tile = queue_.front();
    queue_.pop_front();
    if (static_cast<int>(queue_.size()) < lowMark_ && !asked_) changed_.notify_all(); // time to ask
    return tile;
}

void TileWorker::finished(const tracer::TileResult& result) {
    std::vector<char> message = encodeTile(result);
    std::lock_guard lock(mutex_);
    outbox_.push_back(std::move(message)); // sent at the main thread's next poll
    ++tilesDone_;
}

bool TileWorker::askIfLow() {
    int want = 0;
    {
        std::lock_guard lock(mutex_);
        if (asked_ || noMore_ || renderDone_) return asked_;
        const int target = queueTarget();
        lowMark_ = target / 2;
        if (static_cast<int>(queue_.size()) >= lowMark_) return true;
        want = target - static_cast<int>(queue_.size());
        asked_ = true;
    }
    session_.send(0, kRequestTag, &want, sizeof want);
    return true;
}

void TileWorker::sendResults() {
    std::unique_lock lock(mutex_);
    const bool last = renderDone_;
    const auto now = std::chrono::steady_clock::now();
    if (!last && now - lastSend_ < kSendInterval) return;
    lock.unlock();
    if (!session_.sendFinished(last)) return; // the batch before is still on its way
    lock.lock();
    TileBatch batch(0); // a still: its frame number is not needed
    for (; !outbox_.empty(); outbox_.pop_front()) batch.add(outbox_.front());
    lastSend_ = now;
    lock.unlock();
    if (batch.empty()) return;
    sending_ = std::move(batch);
    session_.startSend(0, kResultTag, sending_->bytes().data(), sending_->bytes().size());
}

/// The main thread's loop: sends finished tiles, asks for more and takes rank 0's answers,
/// until the render threads are done and no question is left unanswered.
void TileWorker::exchange() {
    for (;;) {
        std::unique_lock lock(mutex_);
        const bool over = renderDone_ && !asked_;
        lock.unlock();
        sendResults();
        if (over) {
            session_.sendFinished(true);
            return;
        }
        askIfLow();
        int source = 0, tag = 0, bytes = 0;
        if (!session_.poll(source, tag, bytes)) tag = 0;
        if (tag == kTilesTag) {
            const std::vector<char> message = session_.receive(0, kTilesTag);
            const std::vector<int> tiles = intsOf(message);
            lock.lock();
            asked_ = false;
            noMore_ = tiles.empty();
            queue_.insert(queue_.end(), tiles.begin(), tiles.end());
            changed_.notify_all();
            continue;
        }
        if (tag == kGiveBackTag) {
            giveBack();
            continue;
        }
        lock.lock();
        changed_.wait_for(lock, asked_ ? kAnswerPoll : kIdlePoll);
    }
}

void TileWorker::giveBack() {
    session_.receive(0, kGiveBackTag);
    std::vector<int> back;
    {
        std::lock_guard lock(mutex_);
        const auto count = static_cast<std::ptrdiff_t>(queue_.size() + 1) / 2;
        back.assign(queue_.end() - count, queue_.end());
        queue_.erase(queue_.end() - count, queue_.end());
    }
    session_.send(0, kGivenBackTag, back.data(), back.size() * sizeof(int));
}

void TileWorker::awaitRelease() {
    for (;;) {
        int source = 0, tag = 0, bytes = 0;
        if (!session_.poll(source, tag, bytes)) {
            std::this_thread::sleep_for(kAnswerPoll);
        } else if (tag == kGiveBackTag) {
            giveBack(); // its queue is empty now: the answer says it began every tile
        } else {
            session_.receive(source, tag);
            if (tag == kReleaseTag) return;
        }
    }
}

void TileWorker::render(const scene::SceneDesc* scene, const std::vector<tracer::Tile>& tiles,
                        std::optional<std::chrono::steady_clock::time_point> deadline) {
    queue_.clear();
    outbox_.clear();
    asked_ = renderDone_ = false;
    noMore_ = deadline.has_value(); // a time-limited render asks for nothing
    tilesDone_ = lowMark_ = 0;
    secondsWaited_ = 0;
    start_ = lastSend_ = std::chrono::steady_clock::now();
    std::vector<int> share;
    if (deadline) share = timeLimitedShare(static_cast<int>(tiles.size()), session_.rank(), session_.size());
    tracer::RenderOutcome outcome;
    if (!scene) {
        outcome.error = "the frame was not evaluated";
        renderDone_ = true;
    } else if (deadline && share.empty()) {
        outcome.ok = true; // more ranks than tiles
        renderDone_ = true;
    }
    const bool traces = !renderDone_;
    std::thread renderer([&] {
        if (!traces) return;
        tracer::RenderJob job = renderJob(options_);
        if (deadline) {
            job.progressive->deadline = deadline;
            for (const int t : share) job.tiles.push_back(tiles[static_cast<size_t>(t)]);
            job.onTileDone = [&](const tracer::TileResult& result) {
                finished({result.tile, share[static_cast<size_t>(result.index)], result.channels, result.pixels});
            };
        } else {
            job.tiles = tiles;
            job.nextTile = [this] { return nextTile(); };
            job.onTileDone = [this](const tracer::TileResult& result) { finished(result); };
        }
        try {
            outcome = tracer::render(*scene, job);
        } catch (const std::exception& e) {
            outcome.ok = false;
            outcome.error = e.what();
        }
        std::lock_guard lock(mutex_);
        renderDone_ = true;
        changed_.notify_all();
    });
    exchange();
    renderer.join();
    if (!outcome.ok) session_.send(0, kErrorTag, outcome.error.data(), outcome.error.size());
    session_.send(0, kDoneTag, nullptr, 0);
    awaitRelease();
    session_.sumStats(outcome.stats);
}

} // namespace

int serveRankZero(MpiSession& session, const Options& options, const CompileFrame& compileFrame) {
    CapturedErrors errors;
    lang::Compilation c;
    bool evaluated = false;
    TileWorker worker(session, options);
    for (;;) {
        Command command;
        session.broadcast(command);
        if (command.kind == Command::Stop) return command.status;
        if (command.kind == Command::Evaluate) {
            evaluated = evaluateOnEveryRank(session, options, compileFrame, command.frame, c,
                                            &errors);
            if (evaluated) applyCommandLine(options, *c.scene);
        } else if (command.kind == Command::Render) {
            std::vector<int> corners;
            session.broadcast(corners, 4 * command.tileCount);
            std::optional<std::chrono::steady_clock::time_point> deadline;
            if (options.timeLimit > 0) {
                std::vector<int> left;
                session.broadcast(left, 1);
                deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(left.front());
            }
            if (command.tileCount > 0)
                worker.render(evaluated ? &*c.scene : nullptr, tilesOfCorners(corners), deadline);
        } else if (command.kind == Command::ServeFrames) {
            if (!sameScriptOnEveryRank(session, options)) continue;
            MpiFrameLink link(session);
            FrameWorker(link, session.rank(), options, compileFrame, errors).run();
        }
    }
}

} // namespace crt::crtc::distributed
