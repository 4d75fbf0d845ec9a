// What an interrupted render leaves so that `crtc --continue` can finish it: a log beside the
// output of the frames finished and the tiles traced, with the hash of the scene each belongs
// to. Tiles are kept as the renderer's floats, so a continued render writes the same bits as
// an uninterrupted one.
#pragma once

#include "tracer/renderer.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
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
    /// The log of the output `output` (beside it, hidden: `.name.png.crtc-resume`).
    static std::string pathFor(const std::string& output);

    /// Reads what an earlier run logged; false, with `error` set, when the file exists but is
    /// not a log (a torn last record, from a crash, is dropped silently).
    bool load(const std::string& path, std::string& error);
    /// Starts a log at `path`, keeping what load() read (--continue) or discarding it.
    bool open(const std::string& path, bool keep, std::string& error);
    ~ResumeLog();

    const std::map<int, LoggedFrame>& frames() const { return frames_; }

    void beginFrame(int frame, uint64_t sceneHash);
    /// Logs a traced tile; written to disk at most a second later (see flushSoon).
    void addTile(int frame, const tracer::TileResult& tile);
    void frameDone(int frame);
    /// Writes what is buffered to disk, durably.
    bool flush();
    /// The render finished: the log is of no further use.
    void remove();

  private:
    void record(uint8_t kind, int frame, uint64_t value, const float* data, size_t count);
    void flushSoon();

    std::map<int, LoggedFrame> frames_;
    std::string path_;
    std::FILE* file_ = nullptr;
    bool failed_ = false;
    std::chrono::steady_clock::time_point lastFlush_ = std::chrono::steady_clock::now();
};

} // namespace crt::crtc
