// The MPI module (crt_mpi.so): the only source that includes MPI.
//
// crtc dlopens it when mpirun started it (mpi_module_loader.cpp), so that OpenMPI's libraries
// load only then. Built with hidden visibility: it exports one C function.
#include "mpi_module_abi.hpp"

#include <mpi.h>

#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

namespace {

/// Waits for a request to complete, testing it after pauses rather than spinning as MPI_Wait
/// does on a core that another process or rank 0's threads could use. The pauses start at
/// `first` and double up to 250 µs: a message larger than OpenMPI sends at once waits for the
/// receiver to take it, which a rank polling every millisecond may take that long to do, and
/// waking often meanwhile takes time from the render threads; much longer pauses delay the
/// messages of animations (bench/README.md, "MPI speed-up").
void waitAsleep(MPI_Request& request, std::chrono::microseconds first) {
    constexpr std::chrono::microseconds kLongest(250);
    for (auto pause = first;; pause = std::min(pause * 2, kLongest)) {
        int done = 0;
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(pause);
    }
}

/// Makes every TCP connection of the process send small messages at once.
///
/// OpenMPI's runtime talks to mpirun over a TCP connection that keeps Nagle's algorithm on.
/// In MPI_Finalize each process sends its part of a fence while its last message is not yet
/// acknowledged, and mpirun acknowledges it only when its delayed acknowledgement fires, 40 ms
/// on Linux: every job lost that much at its end. Right after MPI_Init the process's TCP
/// connections are all MPI's (crtc has opened none by then), and OpenMPI sets TCP_NODELAY on
/// those that carry MPI messages already.
void sendTcpAtOnce() {
    DIR* fds = opendir("/proc/self/fd");
    if (!fds) return;
    while (const dirent* entry = readdir(fds)) {
        if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue; // "." and ".."
        const int fd = std::atoi(entry->d_name);
        int domain = 0, type = 0;
        socklen_t length = sizeof domain;
        if (getsockopt(fd, SOL_SOCKET, SO_DOMAIN, &domain, &length) != 0) continue; // not a socket
        length = sizeof type;
        if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0 || type != SOCK_STREAM) continue;
        if (domain != AF_INET && domain != AF_INET6) continue;
        const int on = 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    }
    closedir(fds);
}

void init(int* argc, char*** argv, int* rank, int* size) {
    // OpenMPI's default transport, UCX, takes about 0.2 s of every process's start to set up,
    // as long as a whole render of a small scene, and brings nothing to crtc's few and small
    // messages. Unless the job chose one (mpirun --mca pml ..., or the environment), ob1.
    setenv("OMPI_MCA_pml", "ob1", 0);
    int provided = 0;
    // Only the main thread calls MPI: the render threads hand tiles and results to it.
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
    sendTcpAtOnce();
}

void gatherProcessorNames(char* names) {
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    MPI_Gather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, names, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, 0,
               MPI_COMM_WORLD);
}

void broadcastInts(int* values, int count, int asleep) {
    if (count <= 0) return;
    if (!asleep) {
        MPI_Bcast(values, count, MPI_INT, 0, MPI_COMM_WORLD);
        return;
    }
    MPI_Request request;
    MPI_Ibcast(values, count, MPI_INT, 0, MPI_COMM_WORLD, &request);
    waitAsleep(request, std::chrono::microseconds(200));
}

void allReduceSum(const std::uint64_t* values, std::uint64_t* out, int count) {
    MPI_Allreduce(values, out, count, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
}

void allReduceMax(const std::uint64_t* values, std::uint64_t* out, int count) {
    MPI_Allreduce(values, out, count, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
}

void reduceSumToRoot(const std::uint64_t* values, std::uint64_t* out, int count) {
    MPI_Reduce(values, out, count, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
}

void send(int rank, int tag, const void* data, std::size_t bytes) {
    // A small message leaves at once. When the receiver is behind (rank 0 writing a frame, or
    // kept off its core by the load), wait asleep: MPI_Send would spin on a core the receiver
    // may need.
    MPI_Request request;
    MPI_Isend(data, static_cast<int>(bytes), MPI_BYTE, rank, tag, MPI_COMM_WORLD, &request);
    waitAsleep(request, std::chrono::microseconds(50));
}

/// The send startSend began, while it is not over.
MPI_Request startedSend = MPI_REQUEST_NULL;

void startSend(int rank, int tag, const void* data, std::size_t bytes) {
    MPI_Isend(data, static_cast<int>(bytes), MPI_BYTE, rank, tag, MPI_COMM_WORLD, &startedSend);
}

int sendFinished(int wait) {
    if (startedSend == MPI_REQUEST_NULL) return 1;
    // MPI_Test, here or in waitAsleep, sets a request it finds complete to MPI_REQUEST_NULL.
    if (wait) {
        waitAsleep(startedSend, std::chrono::microseconds(50));
        return 1;
    }
    int done = 0;
    MPI_Test(&startedSend, &done, MPI_STATUS_IGNORE);
    return done;
}

int poll(int* source, int* tag, int* bytes) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return 0;
    *source = status.MPI_SOURCE;
    *tag = status.MPI_TAG;
    MPI_Get_count(&status, MPI_BYTE, bytes);
    return 1;
}

void probe(int source, int tag, int* from, int* bytes) {
    MPI_Status status;
    MPI_Probe(source == kCrtMpiAnySource ? MPI_ANY_SOURCE : source, tag, MPI_COMM_WORLD, &status);
    MPI_Get_count(&status, MPI_BYTE, bytes);
    *from = status.MPI_SOURCE;
}

void receive(int source, int tag, void* data, int bytes) {
    // A large message comes in pieces as fast as its sender hands them over: wait asleep.
    MPI_Request request;
    MPI_Irecv(data, bytes, MPI_BYTE, source, tag, MPI_COMM_WORLD, &request);
    waitAsleep(request, std::chrono::microseconds(50));
}

void abortJob(int status) {
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status); // MPI_Abort does not return; this makes sure of it
}

void finalize() { MPI_Finalize(); }

constexpr CrtMpiModule kModule{kCrtMpiAbiVersion,
                               MPI_MAX_PROCESSOR_NAME,
                               init,
                               gatherProcessorNames,
                               broadcastInts,
                               allReduceSum,
                               allReduceMax,
                               reduceSumToRoot,
                               send,
                               startSend,
                               sendFinished,
                               poll,
                               probe,
                               receive,
                               abortJob,
                               finalize};

} // namespace

extern "C" __attribute__((visibility("default"))) const CrtMpiModule* crt_mpi_module() {
    return &kModule;
}
