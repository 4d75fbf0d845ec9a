// crtc under mpirun, built with MPI.
#include "distributed_render.hpp"

#include "frame_agreement.hpp"
#include "mpi_session.hpp"
#include "tile_dispatcher.hpp"
#include "tile_worker.hpp"

#include <csignal>

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

} // namespace

int renderDistributed(const Options& options, const CompileFrame& compileFrame) {
    MpiSession session(nullptr, nullptr);
    if (session.root()) return renderOnRankZero(session, options, compileFrame);
    return serveRankZero(session, options, compileFrame);
}

} // namespace crt::crtc::distributed
