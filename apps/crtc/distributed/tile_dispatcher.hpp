// Rank 0's side of a shared render: the job's tiles handed out, a few at a time, to rank 0's
// own render threads and to the other ranks as they ask, so that a rank with slower tiles
// simply asks less often; every finished tile delivered to the job's onTileDone.
//
// The protocol, per frame: rank 0 broadcasts the Render command and the tiles; a worker asks
// (kRequestTag) for as many tiles as it can queue, gets their indices (kTilesTag; none: the
// job is handed out), sends the tiles it finished since it last sent (kResultTag), a failure
// (kErrorTag) and at last kDoneTag; then the ranks sum their ray counts on rank 0.
#pragma once

#include "mpi_session.hpp"
#include "tracer/renderer.hpp"

#include <atomic>
#include <mutex>
#include <string>

namespace crt::crtc::distributed {

class TileDispatcher {
  public:
    explicit TileDispatcher(MpiSession& session) : session_(session) {}

    /// Renders `job` over every rank; a TileRenderer (render_command.hpp). Only MPI calls from
    /// this (the main) thread: rank 0's render threads run beside it.
    tracer::RenderOutcome render(const scene::SceneDesc& scene, const tracer::RenderJob& job);

    /// False once a render stopped (Ctrl-C, a signal) without waiting for the other ranks:
    /// their messages are still on the way, so the job can only be aborted.
    bool drained() const { return drained_; }

  private:
    /// The next tiles to hand out, at most `count`: none once the job is handed out, failed
    /// or cancelled.
    std::vector<int> claim(int count);
    void fail(std::string why);
    /// Answers the other ranks' messages until they are done, or the render is cancelled.
    void serveWorkers(const tracer::RenderJob& job, const std::atomic<bool>& localFinished);
    void deliver(const tracer::RenderJob& job, const tracer::TileResult& result);

    MpiSession& session_;
    bool drained_ = true;
    std::mutex mutex_; // guards what follows, shared with rank 0's render threads
    const std::atomic<bool>* cancel_ = nullptr;
    int next_ = 0;
    int tileCount_ = 0;
    int delivered_ = 0;
    std::string error_;
    std::mutex deliverMutex_; // onTileDone sees one tile at a time
};

} // namespace crt::crtc::distributed
