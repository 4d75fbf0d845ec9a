// How crtc finds out that mpirun started it, without MPI: crtc does not link MPI, whose
// libraries would otherwise load (and take time and memory) in every run. Under mpirun the
// session loads them with the module crt_mpi.so (mpi_module_loader.hpp). A crtc built without
// MPI has no module, and says so under mpirun.
#include "distributed_render.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

namespace crt::crtc::distributed {

namespace {

int environmentInt(const char* name, int otherwise) {
    const char* value = std::getenv(name);
    if (!value || !*value) return otherwise;
    char* end = nullptr;
    const long number = std::strtol(value, &end, 10);
    return *end == '\0' && number >= 0 ? static_cast<int>(number) : otherwise;
}

} // namespace

bool underMpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

int launchedWorldSize() {
    return environmentInt("OMPI_COMM_WORLD_SIZE", environmentInt("PMIX_SIZE", 1));
}

int launchedRank() {
    return environmentInt("OMPI_COMM_WORLD_RANK", environmentInt("PMIX_RANK", 0));
}

#ifndef CRT_WITH_MPI
int renderDistributed(const Options& options, const CompileFrame& compileFrame) {
    // One process under mpirun renders as crtc alone does; several would each write the image.
    if (launchedWorldSize() <= 1) return renderFrames(options, compileFrame, renderTilesHere);
    if (launchedRank() == 0)
        std::cerr << "crtc: this crtc was built without MPI, so it cannot share a render over "
                     "the processes of mpirun; run it alone, or build crtc with OpenMPI "
                     "installed (libopenmpi-dev)\n";
    return 2;
}
#endif

} // namespace crt::crtc::distributed
