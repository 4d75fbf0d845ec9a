// The MPI job crtc runs in, through the MPI module.
#include "mpi_session.hpp"

#include "distributed_render.hpp"
#include "mpi_module_loader.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdlib>
#include <iostream>

namespace crt::crtc::distributed {

namespace {

/// The module, or the end of this process: every rank fails alike, so rank 0 alone says why
/// (with the status of a crtc built without MPI) and none has started anything to clean up.
const CrtMpiModule& mpiModuleOrExit() {
    std::string error;
    if (const CrtMpiModule* module = loadMpiModule(error)) return *module;
    // One write: mpirun's own messages about the failed ranks must not land inside the line.
    if (launchedRank() == 0)
        std::cerr << fmt::format("crtc: cannot share the render over the processes of mpirun: {}\n",
                                 error);
    std::exit(2);
}

} // namespace

MpiSession::MpiSession(int* argc, char*** argv) : mpi_(&mpiModuleOrExit()) {
    mpi_->init(argc, argv, &rank_, &size_);
    const auto nameLength = static_cast<size_t>(mpi_->processorNameLength);
    std::vector<char> all(root() ? nameLength * static_cast<size_t>(size_) : 0);
    mpi_->gatherProcessorNames(root() ? all.data() : nullptr);
    if (root())
        for (int r = 0; r < size_; ++r)
            hosts_.emplace_back(all.data() + static_cast<size_t>(r) * nameLength);
}

MpiSession::~MpiSession() { mpi_->finalize(); }

std::string MpiSession::describe(int rank) const {
    if (rank < static_cast<int>(hosts_.size()))
        return fmt::format("rank {} on {}", rank, hosts_[static_cast<size_t>(rank)]);
    return fmt::format("rank {}", rank);
}

void MpiSession::broadcast(Command& command) {
    int values[4] = {command.kind, command.frame, command.tileCount, command.status};
    // The other ranks wait here while rank 0 finishes a frame's file: asleep, not spinning in
    // MPI_Bcast on a core that rank 0's threads could use.
    mpi_->broadcastInts(values, 4, 1);
    command = Command{values[0], values[1], values[2], values[3]};
}

void MpiSession::broadcast(std::vector<int>& values, int count) {
    values.resize(static_cast<size_t>(count));
    mpi_->broadcastInts(values.data(), count, 0);
}

uint64_t MpiSession::sumOverRanks(uint64_t value) {
    uint64_t sum = 0;
    mpi_->allReduceSum(&value, &sum, 1);
    return sum;
}

std::pair<uint64_t, uint64_t> MpiSession::rangeOverRanks(uint64_t value) {
    // One reduction for both: the greatest complement is the complement of the least value.
    uint64_t values[2] = {value, ~value}, greatest[2] = {};
    mpi_->allReduceMax(values, greatest, 2);
    return {~greatest[1], greatest[0]};
}

tracer::RayStats MpiSession::sumStats(const tracer::RayStats& stats) {
    const auto summed = stats.summed();
    const auto greatest = stats.greatest();
    std::array<uint64_t, tracer::RayStats::kSummed> sum{};
    std::array<uint64_t, tracer::RayStats::kGreatest> most{};
    mpi_->reduceSumToRoot(summed.data(), sum.data(), static_cast<int>(sum.size()));
    mpi_->allReduceMax(greatest.data(), most.data(), static_cast<int>(most.size()));
    if (!root()) return stats;
    return tracer::RayStats::fromCounters(sum, most);
}

void MpiSession::send(int rank, Tag tag, const void* data, size_t bytes) {
    mpi_->send(rank, tag, data, bytes);
}

void MpiSession::startSend(int rank, Tag tag, const void* data, size_t bytes) {
    mpi_->startSend(rank, tag, data, bytes);
}

bool MpiSession::sendFinished(bool wait) { return mpi_->sendFinished(wait ? 1 : 0) != 0; }

bool MpiSession::poll(int& source, int& tag, int& bytes) {
    return mpi_->poll(&source, &tag, &bytes) != 0;
}

std::vector<char> MpiSession::receive(int source, int tag) {
    int from = source;
    return receiveMatching(from, tag);
}

std::vector<char> MpiSession::receiveFromAny(int tag, int& source) {
    source = kCrtMpiAnySource;
    return receiveMatching(source, tag);
}

std::vector<char> MpiSession::receiveMatching(int& source, int tag) {
    int bytes = 0;
    mpi_->probe(source, tag, &source, &bytes);
    std::vector<char> data(static_cast<size_t>(bytes));
    mpi_->receive(source, tag, data.data(), bytes);
    return data;
}

void MpiSession::abort(int status) {
    mpi_->abort(status);
    std::_Exit(status); // the module's abort does not return; this says so to the compiler
}

} // namespace crt::crtc::distributed
