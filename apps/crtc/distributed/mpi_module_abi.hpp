// The C table through which MpiSession calls the MPI module crt_mpi.so.
//
// Plain C types only, so that crtc and the module need agree on nothing but this header; crtc
// itself never links MPI, whose libraries then load only in a crtc that mpirun started.
// Every call is made by the main thread (MPI is initialised for that thread's calls only).
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" {

/// Raised whenever a function's signature or meaning changes; crtc refuses other versions.
inline constexpr int kCrtMpiAbiVersion = 2;

/// The name of the module's one exported function.
inline constexpr const char* kCrtMpiEntryName = "crt_mpi_module";

/// A `source` that matches a message from any rank.
inline constexpr int kCrtMpiAnySource = -1;

/// The module's functions, all on MPI_COMM_WORLD. MPI's errors end the job, as MPI's default
/// handler does, so no function reports one.
struct CrtMpiModule {
    int abiVersion;
    /// The room each processor name takes in gatherProcessorNames (MPI_MAX_PROCESSOR_NAME).
    int processorNameLength;
    /// Initialises MPI; sets this process's rank and the number of processes.
    void (*init)(int* argc, char*** argv, int* rank, int* size);
    /// Every rank's processor name, gathered into `names` on rank 0 (size × processorNameLength
    /// chars there, each name null-terminated; null on the other ranks).
    void (*gatherProcessorNames)(char* names);
    /// Rank 0's `count` ints, received into `values` by every rank. With `asleep`, a rank waits
    /// sleeping rather than spinning on a core that rank 0's threads could use.
    void (*broadcastInts)(int* values, int count, int asleep);
    /// Every rank's `count` values summed (or their maximum) into `out`, on every rank.
    void (*allReduceSum)(const std::uint64_t* values, std::uint64_t* out, int count);
    void (*allReduceMax)(const std::uint64_t* values, std::uint64_t* out, int count);
    /// Every rank's `count` values summed into `out` on rank 0.
    void (*reduceSumToRoot)(const std::uint64_t* values, std::uint64_t* out, int count);
    /// Sends `bytes` bytes to `rank`; returns, having waited asleep, once they may be reused.
    void (*send)(int rank, int tag, const void* data, std::size_t bytes);
    /// Starts sending `bytes` bytes to `rank` and returns at once: the data must stay unchanged
    /// until sendFinished says the send is over. One such send at a time.
    void (*startSend)(int rank, int tag, const void* data, std::size_t bytes);
    /// 1 once the send startSend began is over (or none was begun), else 0; with `wait`, waits
    /// asleep until it is over.
    int (*sendFinished)(int wait);
    /// 1 and the source, tag and size in bytes of a message waiting, or 0 when there is none.
    int (*poll)(int* source, int* tag, int* bytes);
    /// Waits for a message from `source` (or kCrtMpiAnySource) with `tag`; sets its source and
    /// size in bytes, for receive to take it.
    void (*probe)(int source, int tag, int* from, int* bytes);
    /// Receives the message probe announced into `data`, waiting asleep while it comes.
    void (*receive)(int source, int tag, void* data, int bytes);
    /// Ends every process of the job with `status`; does not return.
    void (*abort)(int status);
    /// Finalises MPI.
    void (*finalize)();
};

/// The type of the module's exported entry point.
using CrtMpiEntryFn = const CrtMpiModule* (*)();

} // extern "C"
