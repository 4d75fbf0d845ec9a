// crtc under mpirun, built with MPI.
#include "distributed_render.hpp"

#include "captured_errors.hpp"
#include "frame_agreement.hpp"
#include "frame_dispatcher.hpp"
#include "frame_worker.hpp"
#include "mpi_session.hpp"
#include "stop_signals.hpp"
#include "tile_dispatcher.hpp"
#include "tile_worker.hpp"

#include <csignal>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// When one process of a job dies, OpenMPI's mpirun ends the others with SIGCONT, then a second
/// later SIGTERM and, milliseconds after, SIGKILL. Rank 0 stops at the first of them as for
/// Ctrl-C, so that it has the second it needs to remove its temporary file. (mpirun forwards
/// no SIGCONT of its own unless orte_forward_job_control is set.)
void stopWhenMpirunEndsTheJob() {
    struct sigaction interrupt {};
    sigaction(SIGINT, nullptr, &interrupt);
    sigaction(SIGCONT, &interrupt, nullptr);
    sigaction(SIGTERM, &interrupt, nullptr);
}

int renderOnRankZero(MpiSession& session, const Options& options,
                     const CompileFrame& compileFrame) {
    TileDispatcher dispatcher(session);
    auto compileOnEveryRank = [&](int frame, lang::Compilation& c) {
        stopWhenMpirunEndsTheJob(); // renderFrames has set its Ctrl-C handler by now
        Command command{Command::Evaluate, frame, 0, 0};
        session.broadcast(command);
        return evaluateOnEveryRank(session, options, compileFrame, frame, c, nullptr);
    };
    const int status = renderFrames(
        options, compileOnEveryRank,
        [&](const scene::SceneDesc& scene, const tracer::RenderJob& job) {
            return dispatcher.render(scene, job);
        });
    if (!dispatcher.drained()) session.abort(status);
    Command stop{Command::Stop, 0, 0, status};
    session.broadcast(stop);
    return status;
}

/// An animation: each frame evaluated and traced whole on one rank, rank 0 included (its
/// worker runs on a thread beside the dispatcher, which writes every file).
int renderFramesOnRankZero(MpiSession& session, const Options& options,
                           const CompileFrame& compileFrame) {
    Command command{Command::ServeFrames, 0, 0, 0};
    session.broadcast(command);
    if (!sameScriptOnEveryRank(session, options)) {
        Command stop{Command::Stop, 0, 0, 1};
        session.broadcast(stop);
        return 1;
    }
    stopWhenMpirunEndsTheJob();
    FrameDispatcher dispatcher(session, options);
    // The worker's diagnostics are printed with its frame, when the run reaches it: not those
    // of frames evaluated ahead of one that failed.
    CapturedErrors workerErrors(std::this_thread::get_id());
    std::thread worker(
        [&] { FrameWorker(dispatcher.localLink(), 0, options, compileFrame, workerErrors).run(); });
    const int status = renderFedFrames(options, dispatcher);
    dispatcher.finish();
    worker.join();
    Command stop{Command::Stop, 0, 0, status};
    session.broadcast(stop);
    return status;
}

} // namespace

int renderDistributed(const Options& options, const CompileFrame& compileFrame) {
    MpiSession session(nullptr, nullptr);
    int status = 0;
    // A single frame is shared by tiles; the frames of an animation are shared out whole.
    if (!session.root()) {
        setStopNote(""); // rank 0 says what a Ctrl-C left, for the whole job
        status = serveRankZero(session, options, compileFrame);
    }
    else if (options.frames.selected() > 1)
        status = renderFramesOnRankZero(session, options, compileFrame);
    else
        status = renderOnRankZero(session, options, compileFrame);
    // The job is over. Every rank returns its status, so mpirun, seeing the first rank that
    // exits with a failure, ends the others as they finalise MPI: nothing is left to clean up
    // or to say then.
    setStopNote("");
    std::signal(SIGCONT, SIG_DFL);
    return status;
}

} // namespace crt::crtc::distributed
