// Finds and loads the MPI module crt_mpi.so, which crtc dlopens only under mpirun.
#pragma once

#include "mpi_module_abi.hpp"

#include <string>

namespace crt::crtc::distributed {

/// Loads the module named by CRT_MPI_MODULE, or else the first of crt_mpi.so beside the
/// executable (the build tree) and <executable's folder>/../lib/crt/crt_mpi.so (an install).
/// Returns its table, or null with the reason, naming what was tried, in `error`.
const CrtMpiModule* loadMpiModule(std::string& error);

} // namespace crt::crtc::distributed
