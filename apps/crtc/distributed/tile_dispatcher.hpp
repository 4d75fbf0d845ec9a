// Rank 0's side of a shared render: the job's tiles handed out, a few at a time, to rank 0's
// own render threads and to the other ranks as they ask, so that a rank with slower tiles
// simply asks less often; every finished tile delivered to the job's onTileDone. When rank 0's
// threads find no tile left, they take back half of those a worker holds and has not begun,
// as often as it takes, and a worker that asks then gets half of those: costly tiles at the
// end of the order are not left to the rank that queued them. A time-limited render is shared
// differently: each rank refines its own share of the tiles (timeLimitedShare), pass after
// pass, until the deadline rank 0 sends, and then sends them all.
//
// The protocol, per frame: rank 0 broadcasts the Render command and the tiles (and, under a
// time limit, the milliseconds left, after which a worker asks for nothing); a worker asks
// (kRequestTag) for as many tiles as it can queue, gets their indices (kTilesTag; none: the
// job is handed out), sends the tiles it finished since it last sent (kResultTag), answers
// rank 0's kGiveBackTag with tiles it had not begun (kGivenBackTag; none: it has begun all),
// sends a failure (kErrorTag) and at last kDoneTag, then waits for rank 0's kReleaseTag,
// answering what rank 0 asked before it (so that no message is left over for the next frame);
// then the ranks sum their ray counts on rank 0.
#pragma once

#include "mpi_session.hpp"
#include "tracer/renderer.hpp"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

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
    /// What rank 0 knows of one worker's share of the frame.
    struct Worker {
        int held = 0;          ///< tiles handed to it, neither finished nor given back
        bool allBegun = false; ///< it said it had begun every tile it held
        bool askedBack = false, doneSent = false, released = false;
    };

    /// The next tiles for a worker, at most `count`: new ones, else half of those given back;
    /// none once the job is handed out, failed or cancelled.
    std::vector<int> claim(int count);
    /// For rank 0's render threads: a new tile or one given back, waiting while a worker may
    /// still give some back; -1 when none will come.
    int claimLocal();
    bool stopped() const;
    void fail(std::string why);
    /// Answers the other ranks' messages until they are done, or the render is cancelled.
    void serveWorkers(const tracer::RenderJob& job, const std::atomic<bool>& localFinished);
    /// Handles one worker message; the number of workers it released.
    int handle(const tracer::RenderJob& job, int source, int tag, const std::vector<char>& message);
    /// While rank 0's threads wait for tiles: asks each worker holding tiles it may not have
    /// begun to give half of them back. True while they wait.
    bool askForTilesBack();
    /// Ends a worker's part of the frame once it is done and has answered every question.
    int releaseIfDone(int source);
    void deliver(const tracer::RenderJob& job, const tracer::TileResult& result);

    MpiSession& session_;
    bool drained_ = true;
    std::mutex mutex_; // guards what follows, shared with rank 0's render threads
    std::condition_variable givenBack_;
    const std::atomic<bool>* cancel_ = nullptr;
    int next_ = 0;
    int tileCount_ = 0;
    int delivered_ = 0;
    int localWaiting_ = 0;      ///< rank 0's render threads waiting in claimLocal
    std::vector<int> returned_; ///< tiles given back, not yet handed out again
    std::vector<Worker> workers_; ///< by rank; rank 0's entry is unused
    std::string error_;
    std::mutex deliverMutex_; // onTileDone sees one tile at a time
};

} // namespace crt::crtc::distributed
