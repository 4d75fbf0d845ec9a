// crtc under mpirun: one render shared out over the processes of an MPI job. Rank 0 runs the
// render as crtc alone would (frames, output, progress, resume log). A single frame is shared
// by tiles: every rank evaluates it and traces the tiles rank 0 hands it (tile_dispatcher.hpp).
// An animation is shared by frames: each evaluated and traced whole on the rank that asked for
// it, rank 0 included (frame_dispatcher.hpp).
#pragma once

#include "render_command.hpp"

namespace crt::crtc::distributed {

/// Whether this process was started by mpirun (OpenMPI's or PMIx's environment is set).
bool underMpi();
/// The number of processes mpirun started, from the environment; 1 without mpirun.
int launchedWorldSize();
/// This process's rank in the job mpirun started, from the environment; 0 without mpirun.
int launchedRank();

/// renderCommand for a process of an MPI job: every rank calls it with the same options.
/// Returns crtc's exit status (rank 0's is the job's).
int renderDistributed(const Options& options, const CompileFrame& compileFrame);

} // namespace crt::crtc::distributed
