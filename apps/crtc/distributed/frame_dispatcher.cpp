// Rank 0's side of an animation shared out by frames.
#include "frame_dispatcher.hpp"

#include "tile_message.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// How long the main thread sleeps when no message waits (as the tile dispatcher's).
constexpr auto kPollInterval = std::chrono::microseconds(1000);
/// Tiles handed to the run between two looks at the messages, so that workers asking for a
/// frame are not kept waiting while a large frame is written.
constexpr int kTilesBetweenServes = 256;

} // namespace

FrameDispatcher::FrameDispatcher(MpiSession& session, const Options& options)
    : session_(session), options_(options), nextFrame_(options.frames.begin()),
      end_(options.frames.end()), consumed_(nextFrame_), undecided_(nextFrame_),
      // Each worker holds two frames (one asked for ahead), and a few more can be done.
      window_(3 * session.size()) {}

void FrameDispatcher::begin(std::function<bool(int frame, uint64_t hash)> finishedBefore) {
    finishedBefore_ = std::move(finishedBefore);
}

bool FrameDispatcher::serveOnce() {
    bool any = false;
    int source = 0, tag = 0, bytes = 0;
    while (session_.poll(source, tag, bytes)) { // all that waits: no worker waits to send
        handle(source, tag, session_.receive(source, tag));
        any = true;
    }
    std::vector<char> message;
    while (local_.takeFromWorker(tag, message)) {
        handle(0, tag, message);
        any = true;
    }
    return any;
}

void FrameDispatcher::serveUntil(const std::function<bool()>& done) {
    while (!done())
        if (!serveOnce()) std::this_thread::sleep_for(kPollInterval);
}

void FrameDispatcher::answer(int rank, Tag tag, const int* values, int count) {
    const size_t bytes = sizeof(int) * static_cast<size_t>(count);
    if (rank == 0)
        local_.sendToWorker(tag, values, bytes);
    else
        session_.send(rank, tag, values, bytes);
}

FrameDispatcher::Frame* FrameDispatcher::wantedFrame(const std::vector<char>& message) {
    int32_t frame = -1;
    if (message.size() >= sizeof frame) std::memcpy(&frame, message.data(), sizeof frame);
    const auto found = frames_.find(frame);
    // Gone: passed by the run; not wanted: reused, finished before, or after a failure.
    if (found == frames_.end() || !found->second.wanted) return nullptr;
    return &found->second;
}

void FrameDispatcher::handle(int source, int tag, const std::vector<char>& message) {
    if (tag == kFrameRequestTag) return handOut(source);
    if (tag == kFactsTag) return takeFacts(source, message);
    if (tag == kFrameTileTag) return takeTile(source, message);
    if (tag == kIdleTag) {
        ++idleRanks_;
        return;
    }
    Frame* f = wantedFrame(message);
    if (!f) return;
    if (tag == kFrameErrorTag && f->error.empty()) {
        f->error = fmt::format("{}: {}", session_.describe(source),
                               std::string(message.begin() + sizeof(int32_t), message.end()));
    } else if (tag == kFrameDoneTag) {
        FrameDone done;
        if (splitText(message, done)) f->outcome = outcomeOf(done);
        f->traced = true;
    }
}

void FrameDispatcher::handOut(int rank) {
    if (closed_ || nextFrame_ >= end_) {
        const int none = -1;
        answer(rank, kFrameTag, &none, 1);
        return;
    }
    // The run writes frames in order: a slow frame holds those after it here, at most window_.
    if (nextFrame_ >= consumed_ + window_) {
        waiting_.push_back(rank);
        return;
    }
    frames_[nextFrame_].rank = rank;
    answer(rank, kFrameTag, &nextFrame_, 1);
    ++nextFrame_;
}

void FrameDispatcher::takeFacts(int rank, const std::vector<char>& message) {
    FrameFacts facts;
    std::string messages;
    if (!splitText(message, facts, &messages)) return;
    const auto found = frames_.find(facts.frame);
    if (found == frames_.end() || found->second.rank != rank) return;
    Frame& f = found->second;
    f.evaluated = true;
    f.facts = facts;
    f.messages = std::move(messages);
    const tracer::Tile region =
        options_.region.value_or(tracer::Tile{0, 0, facts.width, facts.height});
    if (facts.ok && region.x1 <= facts.width && region.y1 <= facts.height)
        f.tileList = tracer::regionTiles(region);
    decide();
}

void FrameDispatcher::decide() {
    for (auto found = frames_.find(undecided_); found != frames_.end() && found->second.evaluated;
         found = frames_.find(++undecided_)) {
        Frame& f = found->second;
        f.decided = true;
        if (!f.facts.ok) {
            // The run stops at this frame: no frame after it is handed out.
            if (failedFrame_ < 0) failedFrame_ = undecided_;
            end_ = std::min(end_, undecided_ + 1);
            previous_ = f.facts;
            continue;
        }
        // The run's own rule: a frame whose scene is the previous one's reuses its image.
        f.unchanged =
            undecided_ > options_.frames.begin() && previous_.ok && f.facts.sameScene(previous_);
        previous_ = f.facts;
        f.wanted = !closed_ && failedFrame_ < 0 && !f.unchanged &&
                   !(finishedBefore_ && finishedBefore_(undecided_, f.facts.hash));
        if (!f.wanted) f.tiles.clear();
        const int verdict[2] = {undecided_, f.wanted ? 1 : 0};
        answer(f.rank, kVerdictTag, verdict, 2);
    }
}

void FrameDispatcher::takeTile(int rank, const std::vector<char>& message) {
    Frame* f = wantedFrame(message);
    if (!f) return;
    bool valid = true;
    const bool whole = TileBatch::split(message, [&](const std::vector<char>& tile) {
        std::vector<float> pixels;
        int index = 0;
        if (!decodeTile(tile, f->tileList, channels(), pixels, index)) {
            valid = false;
            return;
        }
        const tracer::Tile& t = f->tileList[static_cast<size_t>(index)];
        f->tiles[{t.x0, t.y0}] = std::move(pixels);
    });
    if ((!whole || !valid) && f->error.empty())
        f->error = fmt::format("{} sent a tile that is not one of frame {}'s",
                               session_.describe(rank), f->facts.frame);
}

void FrameDispatcher::report(int frame, const Frame& f) const {
    // One write, so that what mpirun prints about the other ranks cannot split it.
    const std::string heading =
        f.facts.ok ? ""
                   : fmt::format("crtc: {} cannot evaluate frame {}:\n", session_.describe(f.rank), frame);
    std::cerr << heading + f.messages;
}

FedFrame FrameDispatcher::next(int frame) {
    consumed_ = frame;
    frames_.erase(frames_.begin(), frames_.lower_bound(frame));
    while (!waiting_.empty() && nextFrame_ < consumed_ + window_) {
        const int rank = waiting_.front();
        waiting_.pop_front();
        handOut(rank);
    }
    serveUntil([&] {
        const auto found = frames_.find(frame);
        return found != frames_.end() && found->second.decided;
    });
    const Frame& f = frames_.at(frame);
    report(frame, f);
    FedFrame fed;
    if (!f.facts.ok) return fed;
    fed.ok = true;
    fed.unchanged = f.unchanged;
    fed.width = f.facts.width;
    fed.height = f.facts.height;
    fed.gamma = f.facts.gamma;
    fed.srgb = f.facts.srgb != 0;
    fed.hash = f.facts.hash;
    return fed;
}

tracer::RenderOutcome FrameDispatcher::render(const tracer::RenderJob& job) {
    Frame& f = frames_.at(consumed_);
    tracer::RenderOutcome outcome;
    outcome.tileCount = static_cast<int>(job.tiles.size());
    if (job.tiles.empty()) { // every tile came from the resume log
        outcome.ok = true;
        return outcome;
    }
    if (!f.wanted) {
        outcome.error =
            fmt::format("frame {} was not traced: its file went while the job ran", consumed_);
        return outcome;
    }
    auto cancelled = [&] { return job.cancel && job.cancel->load(); };
    serveUntil([&] { return f.traced || cancelled(); });
    if (f.traced) outcome = f.outcome;
    outcome.tileCount = static_cast<int>(job.tiles.size());
    outcome.ok = false;
    if (!f.error.empty()) {
        outcome.error = f.error;
        return outcome;
    }
    for (size_t i = 0; i < job.tiles.size(); ++i) {
        if (cancelled()) {
            outcome.cancelled = true;
            return outcome;
        }
        const tracer::Tile& tile = job.tiles[i];
        const auto pixels = f.tiles.find({tile.x0, tile.y0});
        if (pixels == f.tiles.end()) {
            outcome.error = fmt::format("{} did not send every tile of frame {}",
                                        session_.describe(f.rank), consumed_);
            return outcome;
        }
        if (job.onTileDone)
            job.onTileDone(tracer::TileResult{tile, static_cast<int>(i), channels(), pixels->second});
        f.tiles.erase(pixels);
        ++outcome.tilesDone;
        if ((i + 1) % kTilesBetweenServes == 0) serveOnce();
    }
    outcome.ok = true;
    return outcome;
}

void FrameDispatcher::finish() {
    closed_ = true;
    finishedBefore_ = nullptr; // the run that answered it is over
    while (!waiting_.empty()) {
        handOut(waiting_.front());
        waiting_.pop_front();
    }
    for (auto& [frame, f] : frames_) {
        if (f.decided && f.wanted && !f.traced) answer(f.rank, kCancelTag, &frame, 1);
        if (f.decided) f.wanted = false;
    }
    decide();
    serveUntil([&] { return idleRanks_ == session_.size(); });
}

} // namespace crt::crtc::distributed
