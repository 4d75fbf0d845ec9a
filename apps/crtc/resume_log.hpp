// What an interrupted render leaves so that `crtc --continue` can finish it: a log beside the
// output of the frames finished and the tiles traced, with the hash of the scene each belongs
// to. Tiles are kept as the renderer's floats, so a continued render writes the same bits as
// an uninterrupted one.
//
// The file only pays for itself where losing it would hurt: a frame's tiles are logged once
// the frame has been rendering a while (a few seconds by default), a finished frame of an
// animation at once; the file is created with the first record logged. Records are written in
// blocks and synced to disk at most once a second. A short render leaves nothing but its image.
#pragma once

#include "tracer/renderer.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace crt::crtc {

/// A frame as an earlier run of the same output left it.
struct LoggedFrame {
    uint64_t sceneHash = 0;
    bool done = false; ///< its image was written
    /// Traced tiles of an unfinished frame, by their index in the frame's tile list.
    std::map<int, std::vector<float>> tiles;
};

class ResumeLog {
  public:
    using Clock = std::chrono::steady_clock;

    /// The log of the output `output` (beside it, hidden: `.name.png.crtc-resume`).
    static std::string pathFor(const std::string& output);

    /// Reads what an earlier run logged; false, with `error` set, when the file exists but is
    /// not a log (a torn last record, from a crash, is dropped silently).
    bool load(const std::string& path, std::string& error);
    /// Sets out to log the render at `path`, keeping what load() read (--continue) or
    /// discarding it, together with any log an earlier run left there. A frame's tiles are
    /// logged once it has been rendering for `tileDelay`. `onStartedOrStopped` is called when
    /// the file is created, and when it is given up after a failure to write it (which is
    /// said, as a warning).
    void prepare(const std::string& path, bool keep, Clock::duration tileDelay,
                 std::function<void()> onStartedOrStopped);
    /// Creates the file now and writes everything known so far; false, with `error` set, when
    /// it cannot be written (the log then stays off).
    bool start(std::string& error);
    ~ResumeLog();

    const std::map<int, LoggedFrame>& frames() const { return frames_; }
    /// Whether the file exists: an interruption from now on can be continued.
    bool started() const { return fd_ >= 0; }

    void beginFrame(int frame, uint64_t sceneHash);
    /// Logs a traced tile of the frame begun last, if the frame has been rendering for the
    /// delay: written to the file within a second.
    void addTile(int frame, const tracer::TileResult& tile);
    /// Logs that the frame's image is complete: written to the file at once.
    void frameDone(int frame);
    /// The render finished: the log is of no further use.
    void remove();

  private:
    void record(uint8_t kind, int frame, uint64_t value, const float* data, size_t count);
    bool startOrGiveUp();
    bool writePending();
    void writeSoon();
    void giveUp(const std::string& why);
    std::string writeError() const;

    std::map<int, LoggedFrame> frames_;
    std::string path_;
    int fd_ = -1;
    bool failed_ = false;
    Clock::duration tileDelay_{};
    Clock::time_point frameStart_; ///< when the frame begun last began
    std::function<void()> onStartedOrStopped_;
    std::vector<unsigned char> pending_; ///< records not yet written to the file
    Clock::time_point lastWrite_, lastSync_;
};

} // namespace crt::crtc
