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
    : session_(session), options_(options), working_(static_cast<size_t>(session.size()), -1),
      nextFrame_(options.frames.begin()), end_(options.frames.end()), consumed_(nextFrame_),
      undecided_(nextFrame_), window_(2 * session.size()) {}

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

void FrameDispatcher::answer(int rank, Tag tag, int value) {
    if (rank == 0)
        local_.sendToWorker(tag, &value, sizeof value);
    else
        session_.send(rank, tag, &value, sizeof value);
}

void FrameDispatcher::handle(int source, int tag, const std::vector<char>& message) {
    if (tag == kFrameRequestTag) return handOut(source);
    if (tag == kFactsTag) return takeFacts(source, message);
    if (tag == kResultTag) return takeTile(source, message);
    const auto found = frames_.find(working_[static_cast<size_t>(source)]);
    if (found == frames_.end()) return; // a frame the run no longer needs
    Frame& f = found->second;
    if (tag == kErrorTag && f.error.empty()) {
        f.error = fmt::format("{}: {}", session_.describe(source),
                              std::string(message.begin(), message.end()));
    } else if (tag == kFrameDoneTag) {
        FrameDone done;
        if (splitText(message, done)) f.outcome = outcomeOf(done);
        f.traced = true;
        working_[static_cast<size_t>(source)] = -1;
    }
}

void FrameDispatcher::handOut(int rank) {
    if (closed_ || nextFrame_ >= end_) {
        answer(rank, kFrameTag, -1);
        ++idleRanks_;
        return;
    }
    // The run writes frames in order: a slow frame holds those after it here, at most window_.
    if (nextFrame_ >= consumed_ + window_) {
        waiting_.push_back(rank);
        return;
    }
    frames_[nextFrame_].rank = rank;
    working_[static_cast<size_t>(rank)] = nextFrame_;
    answer(rank, kFrameTag, nextFrame_++);
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
    if (!facts.ok) working_[static_cast<size_t>(rank)] = -1;
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
        f.unchanged = undecided_ > options_.frames.begin() && previous_.ok && f.facts.sameScene(previous_);
        previous_ = f.facts;
        bool trace = !closed_ && failedFrame_ < 0 && !f.unchanged;
        if (trace && finishedBefore_ && finishedBefore_(undecided_, f.facts.hash)) trace = false;
        if (trace) {
            const tracer::Tile region = options_.region.value_or(
                tracer::Tile{0, 0, f.facts.width, f.facts.height});
            if (region.x1 <= f.facts.width && region.y1 <= f.facts.height)
                f.tileList = tracer::regionTiles(region);
        } else {
            working_[static_cast<size_t>(f.rank)] = -1;
        }
        f.tracing = trace;
        answer(f.rank, kVerdictTag, trace ? 1 : 0);
    }
}

void FrameDispatcher::takeTile(int rank, const std::vector<char>& message) {
    const auto found = frames_.find(working_[static_cast<size_t>(rank)]);
    if (found == frames_.end() || !found->second.tracing) return;
    Frame& f = found->second;
    std::vector<float> rgb;
    int index = 0;
    if (!decodeTile(message, f.tileList, rgb, index)) {
        if (f.error.empty())
            f.error = fmt::format("{} sent a tile that is not one of frame {}'s",
                                  session_.describe(rank), found->first);
        return;
    }
    const tracer::Tile& tile = f.tileList[static_cast<size_t>(index)];
    f.tiles[{tile.x0, tile.y0}] = std::move(rgb);
}

void FrameDispatcher::report(int frame, const Frame& f) const {
    if (!f.facts.ok)
        std::cerr << fmt::format("crtc: {} cannot evaluate frame {}:\n", session_.describe(f.rank), frame);
    std::cerr << f.messages;
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
    if (!f.tracing && !f.traced) {
        outcome.error = fmt::format("frame {} was not traced: its file went while the job ran", consumed_);
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
        const auto rgb = f.tiles.find({tile.x0, tile.y0});
        if (rgb == f.tiles.end()) {
            outcome.error = fmt::format("{} did not send every tile of frame {}",
                                        session_.describe(f.rank), consumed_);
            return outcome;
        }
        if (job.onTileDone) job.onTileDone(tracer::TileResult{tile, static_cast<int>(i), rgb->second});
        f.tiles.erase(rgb);
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
    for (const auto& [frame, f] : frames_)
        if (f.tracing && !f.traced) answer(f.rank, kCancelTag, frame);
    decide();
    serveUntil([&] { return idleRanks_ == session_.size(); });
}

} // namespace crt::crtc::distributed
