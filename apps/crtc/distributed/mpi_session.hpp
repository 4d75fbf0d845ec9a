// The MPI job crtc runs in: initialised for the main thread's calls only (the render threads
// never call MPI), the commands rank 0 broadcasts, and the messages of a shared render. MPI is
// called through the module crt_mpi.so (mpi_module_abi.hpp), loaded when a session starts.
#pragma once

#include "tracer/stats.hpp"

#include <cstdint>
#include <string>
#include <vector>

struct CrtMpiModule;

namespace crt::crtc::distributed {

/// Point-to-point messages of a shared render (see tile_dispatcher.hpp).
enum Tag : int {
    kRequestTag = 1,   ///< worker → 0: an int, how many more tiles it can take
    kTilesTag,         ///< 0 → worker: tile indices; none: there are no more
    kResultTag,        ///< worker → 0: tiles it finished since it last sent (a TileBatch)
    kErrorTag,         ///< worker → 0: why its render failed (text)
    kDoneTag,          ///< worker → 0: it has sent its last result of the frame
    kGiveBackTag,      ///< 0 → worker: give back half the tiles you have not begun (no data)
    kGivenBackTag,     ///< worker → 0: tile indices it will not trace; none: it began them all
    kReleaseTag,       ///< 0 → worker: every question answered, the frame is over for you
    kEvaluationTag,    ///< worker → 0: why it could not evaluate a frame (text)
    // An animation's frames shared out whole (frame_dispatcher.hpp):
    kFrameRequestTag, ///< worker → 0: it can take a frame (no data)
    kFrameTag,        ///< 0 → worker: an int, the frame to evaluate; -1: no more
    kFactsTag,        ///< worker → 0: the frame evaluated (FrameFacts, then its messages)
    kFrameTileTag,    ///< worker → 0: the frame's tiles it finished since it last sent (a TileBatch)
    kFrameErrorTag,   ///< worker → 0: the frame's number, then why its render failed (text)
    kFrameDoneTag,    ///< worker → 0: the frame traced (FrameDone) after its tiles
    kVerdictTag,      ///< 0 → worker: two ints, the frame and 1 if it is wanted, 0 if not
    kCancelTag,       ///< 0 → worker: an int, a frame no longer wanted
    kIdleTag,         ///< worker → 0: it has finished its last frame (no data)
};

/// What rank 0 tells every rank to do next, broadcast.
struct Command {
    enum Kind : int { Evaluate, Render, ServeFrames, Stop };
    int kind = Stop;
    int frame = 0;     ///< Evaluate: the frame
    int tileCount = 0; ///< Render: how many tiles the job has (their list follows)
    int status = 0;    ///< Stop: crtc's exit status
};

class MpiSession {
  public:
    /// Loads the MPI module and initialises MPI. Without the module, the job cannot go on:
    /// rank 0 says why (naming where the module was looked for) and every rank exits with 2.
    MpiSession(int* argc, char*** argv);
    /// Finalises MPI, unless abort() ended the job.
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool root() const { return rank_ == 0; }
    /// "rank 2 on node7", for messages.
    std::string describe(int rank) const;

    /// Rank 0 sends `command` to every rank, which receives it.
    void broadcast(Command& command);
    /// Rank 0 sends `values` to every rank (each resized to `count` first).
    void broadcast(std::vector<int>& values, int count);

    /// Every rank's `value` summed on every rank.
    uint64_t sumOverRanks(uint64_t value);
    /// The least and the greatest `value` over the ranks, on every rank.
    std::pair<uint64_t, uint64_t> rangeOverRanks(uint64_t value);
    /// The ranks' ray counts summed on rank 0.
    tracer::RayStats sumStats(const tracer::RayStats& stats);

    /// Sends bytes to `rank`; returns once they may be reused.
    void send(int rank, Tag tag, const void* data, size_t bytes);
    /// Starts sending bytes to `rank` and returns at once: they must stay as they are until
    /// sendFinished says the send is over. One such send at a time.
    void startSend(int rank, Tag tag, const void* data, size_t bytes);
    /// Whether the send startSend began is over (true when none was begun); with `wait`, waits
    /// for it to be.
    bool sendFinished(bool wait);
    /// Whether a message is waiting; if so, its source, tag and size in bytes.
    bool poll(int& source, int& tag, int& bytes);
    /// Receives the message poll() announced, or waits for one from `source` with `tag`.
    std::vector<char> receive(int source, int tag);
    /// Waits for a message with `tag` from any rank; `source` is set to its rank.
    std::vector<char> receiveFromAny(int tag, int& source);

    /// Ends every process of the job at once: for when the ranks can no longer agree.
    [[noreturn]] void abort(int status);

  private:
    std::vector<char> receiveMatching(int& source, int tag);

    const CrtMpiModule* mpi_ = nullptr;
    int rank_ = 0;
    int size_ = 1;
    std::vector<std::string> hosts_; ///< rank 0 only: each rank's host name
};

} // namespace crt::crtc::distributed
