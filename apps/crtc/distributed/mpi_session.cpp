// The MPI job crtc runs in.
#include "mpi_session.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <thread>

namespace crt::crtc::distributed {

namespace {

/// The ray counts as an array, to be summed by MPI.
constexpr int kStatCount = 7;
std::array<uint64_t, kStatCount> statArray(const tracer::RayStats& s) {
    return {s.cameraRays,   s.reflectionRays,    s.refractionRays, s.shadowRays,
            s.nodesVisited, s.intersectionTests, s.cachedFrames};
}

/// Waits for a request to complete, testing it every 50 us rather than spinning as MPI_Wait does.
void waitAsleep(MPI_Request& request) {
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
}

} // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
    int provided = 0;
    // Only the main thread calls MPI: the render threads hand tiles and results to it.
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    std::vector<char> all(static_cast<size_t>(MPI_MAX_PROCESSOR_NAME) * size_);
    MPI_Gather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME,
               MPI_CHAR, 0, MPI_COMM_WORLD);
    if (root())
        for (int r = 0; r < size_; ++r)
            hosts_.emplace_back(all.data() + static_cast<size_t>(r) * MPI_MAX_PROCESSOR_NAME);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

std::string MpiSession::describe(int rank) const {
    if (rank < static_cast<int>(hosts_.size()))
        return fmt::format("rank {} on {}", rank, hosts_[static_cast<size_t>(rank)]);
    return fmt::format("rank {}", rank);
}

void MpiSession::broadcast(Command& command) {
    int values[4] = {command.kind, command.frame, command.tileCount, command.status};
    // The other ranks wait here while rank 0 finishes a frame's file: asleep, not spinning in
    // MPI_Bcast on a core that rank 0's threads could use.
    MPI_Request request;
    MPI_Ibcast(values, 4, MPI_INT, 0, MPI_COMM_WORLD, &request);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) break;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    command = Command{values[0], values[1], values[2], values[3]};
}

void MpiSession::broadcast(std::vector<int>& values, int count) {
    values.resize(static_cast<size_t>(count));
    if (count > 0) MPI_Bcast(values.data(), count, MPI_INT, 0, MPI_COMM_WORLD);
}

uint64_t MpiSession::sumOverRanks(uint64_t value) {
    uint64_t sum = 0;
    MPI_Allreduce(&value, &sum, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    return sum;
}

std::pair<uint64_t, uint64_t> MpiSession::rangeOverRanks(uint64_t value) {
    // One reduction for both: the greatest complement is the complement of the least value.
    uint64_t values[2] = {value, ~value}, greatest[2] = {};
    MPI_Allreduce(values, greatest, 2, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
    return {~greatest[1], greatest[0]};
}

tracer::RayStats MpiSession::sumStats(const tracer::RayStats& stats) {
    const std::array<uint64_t, kStatCount> mine = statArray(stats);
    std::array<uint64_t, kStatCount> sum{};
    MPI_Reduce(mine.data(), sum.data(), kStatCount, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    if (!root()) return stats;
    return tracer::RayStats{sum[0], sum[1], sum[2], sum[3], sum[4], sum[5], sum[6]};
}

void MpiSession::send(int rank, Tag tag, const void* data, size_t bytes) {
    // A small message leaves at once. When the receiver is behind (rank 0 writing a frame, or
    // kept off its core by the load), wait asleep: MPI_Send would spin on a core the receiver
    // may need.
    MPI_Request request;
    MPI_Isend(data, static_cast<int>(bytes), MPI_BYTE, rank, tag, MPI_COMM_WORLD, &request);
    waitAsleep(request);
}

bool MpiSession::poll(int& source, int& tag, int& bytes) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    source = status.MPI_SOURCE;
    tag = status.MPI_TAG;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    return true;
}

std::vector<char> MpiSession::receive(int source, int tag) {
    int from = source;
    return receiveMatching(from, tag);
}

std::vector<char> MpiSession::receiveFromAny(int tag, int& source) {
    source = MPI_ANY_SOURCE;
    return receiveMatching(source, tag);
}

std::vector<char> MpiSession::receiveMatching(int& source, int tag) {
    MPI_Status status;
    MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::vector<char> data(static_cast<size_t>(bytes));
    source = status.MPI_SOURCE;
    // A large message comes in pieces as fast as its sender hands them over: wait asleep.
    MPI_Request request;
    MPI_Irecv(data.data(), bytes, MPI_BYTE, source, tag, MPI_COMM_WORLD, &request);
    waitAsleep(request);
    return data;
}

void MpiSession::abort(int status) {
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status); // MPI_Abort does not return; this says so to the compiler
}

} // namespace crt::crtc::distributed
