// Rank 0's side of an animation shared out by frames: the frames handed out one at a time, in
// order, to the ranks as they ask (rank 0's own worker, on a thread, asks like the others);
// each evaluated and traced on the rank that got it; the results fed in order to the run that
// writes the files (render_command.hpp's FrameFeed).
//
// The protocol, per frame: a worker asks (kFrameRequestTag) and gets a frame number (kFrameTag;
// -1: no more), and asks for its next frame as soon as it begins one. It evaluates the frame,
// sends what rank 0 needs to know of it (kFactsTag: FrameFacts, then the diagnostics of its
// evaluation) and traces it at once, sending its tiles (kFrameTileTag), kFrameErrorTag if the
// render failed, and at last kFrameDoneTag with its ray counts. Rank 0 decides, in frame
// order, whether the frame is wanted: not if its scene is the previous frame's (the run reuses
// that image) nor if --continue finds it finished; it says so (kVerdictTag), and the worker
// stops tracing a frame not wanted. Rank 0 cancels the frames being traced when the run stops
// (kCancelTag). A worker told there are no more frames says when it is idle (kIdleTag).
#pragma once

#include "frame_link.hpp"
#include "frame_message.hpp"
#include "mpi_session.hpp"
#include "render_command.hpp"

#include <deque>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace crt::crtc::distributed {

class FrameDispatcher final : public FrameFeed {
  public:
    FrameDispatcher(MpiSession& session, const Options& options);

    void begin(std::function<bool(int frame, uint64_t hash)> finishedBefore) override;
    FedFrame next(int frame) override;
    tracer::RenderOutcome render(const tracer::RenderJob& job) override;

    /// After the run, finished or not: hands out no more frames, cancels those being traced and
    /// waits until every worker has stopped.
    void finish();
    /// The link of the worker that runs on rank 0.
    FrameLink& localLink() { return local_; }

  private:
    struct Frame {
        int rank = -1;
        bool evaluated = false, decided = false, unchanged = false;
        bool wanted = true; ///< until decided otherwise: the worker traces it meanwhile
        bool traced = false;
        FrameFacts facts;
        std::string messages;                                    ///< the evaluation's diagnostics
        std::map<std::pair<int, int>, std::vector<float>> tiles; ///< by top left corner
        std::vector<tracer::Tile> tileList;
        tracer::RenderOutcome outcome;
        std::string error;
    };

    /// Handles the messages waiting, MPI's and the local worker's; false if there were none.
    bool serveOnce();
    void serveUntil(const std::function<bool()>& done);
    void handle(int source, int tag, const std::vector<char>& message);
    void handOut(int rank);
    void takeFacts(int rank, const std::vector<char>& message);
    void takeTile(int rank, const std::vector<char>& message);
    /// The frame a worker's message names, if the run may still need it.
    Frame* wantedFrame(const std::vector<char>& message);
    /// Decides the frames evaluated so far, in order, and answers their workers.
    void decide();
    void answer(int rank, Tag tag, const int* values, int count);
    /// Prints what the rank that evaluated `frame` said of it (its warnings, or why it failed).
    void report(int frame, const Frame& f) const;
    /// Floats a pixel of the tiles workers send (RenderJob::channels).
    int channels() const { return renderJob(options_).channels(); }

    MpiSession& session_;
    const Options& options_;
    LocalFrameLink local_;
    std::function<bool(int, uint64_t)> finishedBefore_;
    std::map<int, Frame> frames_; ///< handed out and not yet passed by the run
    std::deque<int> waiting_;     ///< ranks that asked while too many frames were ahead
    int nextFrame_ = 0, end_ = 0;
    int consumed_ = 0;  ///< the frame the run takes next, or takes now
    int undecided_ = 0; ///< the first frame not yet decided
    int window_ = 0;    ///< frames handed out beyond consumed_, at most: bounds what waits here
    int failedFrame_ = -1;
    bool closed_ = false;
    int idleRanks_ = 0;   ///< workers that have finished their last frame
    FrameFacts previous_; ///< of frame undecided_ - 1
};

} // namespace crt::crtc::distributed
