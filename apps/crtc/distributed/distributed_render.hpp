// crtc under mpirun: one render shared out over the processes of an MPI job. Rank 0 runs the
// render as crtc alone would (frames, output, progress, resume log), its tiles traced by every
// rank; the other ranks evaluate the same frames and trace the tiles rank 0 hands them.
#pragma once

#include "render_command.hpp"

namespace crt::crtc::distributed {

/// Whether this process was started by mpirun (OpenMPI's or PMIx's environment is set).
bool underMpi();
/// The number of processes mpirun started, from the environment; 1 without mpirun.
int launchedWorldSize();

/// renderCommand for a process of an MPI job: every rank calls it with the same options.
/// Returns crtc's exit status (rank 0's is the job's).
int renderDistributed(const Options& options, const CompileFrame& compileFrame);

} // namespace crt::crtc::distributed
