// The side of a shared render on the ranks other than 0: they evaluate the frame rank 0
// evaluates and trace the tiles it hands them (tile_dispatcher.hpp has the protocol), or take
// whole frames of an animation (frame_worker.hpp).
#pragma once

#include "mpi_session.hpp"
#include "render_command.hpp"

namespace crt::crtc::distributed {

/// For tests: set to N, a worker keeps N tiles queued per render thread whatever they cost,
/// so that one 2-process job of a small image makes rank 0 take tiles back.
inline constexpr const char* kTestQueuedTilesVariable = "CRT_TEST_QUEUED_TILES";

/// Follows rank 0's commands until it says stop; returns the job's exit status. Standard error
/// is kept for rank 0, which prints it if this rank fails.
int serveRankZero(MpiSession& session, const Options& options, const CompileFrame& compileFrame);

} // namespace crt::crtc::distributed
