// A rank's side of an animation shared out by frames: it asks rank 0 for a frame, evaluates it,
// tells rank 0 what it found and traces it, unless rank 0 says it is not wanted
// (frame_dispatcher.hpp has the protocol). Every rank runs one, rank 0 on a thread beside its
// dispatcher.
#pragma once

#include "captured_errors.hpp"
#include "frame_link.hpp"
#include "render_command.hpp"

#include <deque>

namespace crt::crtc::distributed {

class FrameWorker {
  public:
    /// `captured`: what this worker writes to standard error, sent to rank 0 with each frame's
    /// facts, which prints it when the run reaches the frame.
    FrameWorker(FrameLink& link, int rank, const Options& options, const CompileFrame& compileFrame,
                CapturedErrors& captured)
        : link_(link), rank_(rank), options_(options), compileFrame_(compileFrame),
          captured_(captured) {}

    /// Takes frames until rank 0 has no more.
    void run();

  private:
    /// The answer to this worker's oldest request for a frame: a frame, or -1.
    int awaitFrame();
    /// Handles a message of the dispatcher's; true if it says `frame` is not wanted.
    bool unwanted(int frame, int tag, const std::vector<char>& message);
    void work(int frame);
    /// Traces `tiles` of the evaluated scene, sending them as they are finished, until done or
    /// rank 0 says the frame is not wanted.
    void trace(int frame, const scene::SceneDesc& scene, const std::vector<tracer::Tile>& tiles);

    FrameLink& link_;
    const int rank_;
    const Options& options_;
    const CompileFrame& compileFrame_;
    CapturedErrors& captured_;
    std::deque<int> answers_; ///< frames rank 0 handed out while this worker was busy
};

} // namespace crt::crtc::distributed
