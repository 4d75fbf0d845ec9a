// The resume log: a header, then records appended as the render goes:
//   kind (1 byte: frame begun, tile, frame done), frame (int32), value (uint64: the scene's
//   hash, or the tile's index), count (uint64) and `count` floats (a tile's RGB).
// Numbers are in the machine's byte order: a log is continued where it was written.
#include "resume_log.hpp"

#include "terminal_text.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace crt::crtc {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'C', 'R', 'T', 'R', 'S', 'M', '1', '\0'};
enum RecordKind : uint8_t { kFrameBegun = 1, kTile = 2, kFrameDone = 3 };
/// No tile holds more floats than this (a 4096 × 4096 tile): a larger count is a damaged log.
constexpr uint64_t kMaxTileFloats = uint64_t{4096} * 4096 * 4;
/// What is logged reaches the file within this time, and is synced to disk at most this often:
/// a crash of the machine loses at most the last period's tiles.
constexpr auto kWritePeriod = std::chrono::seconds(1);
/// Records are written sooner when this many bytes wait, so that a very fast render of a huge
/// image does not gather a second of tiles in memory.
constexpr size_t kBlockBytes = size_t{4} << 20;

struct RecordHeader {
    uint8_t kind;
    int32_t frame;
    uint64_t value;
    uint64_t count;
};

bool readRecordHeader(std::FILE* file, RecordHeader& h) {
    return std::fread(&h.kind, 1, 1, file) == 1 &&
           std::fread(&h.frame, sizeof h.frame, 1, file) == 1 &&
           std::fread(&h.value, sizeof h.value, 1, file) == 1 &&
           std::fread(&h.count, sizeof h.count, 1, file) == 1;
}

void append(std::vector<unsigned char>& bytes, const void* data, size_t size) {
    const size_t end = bytes.size();
    bytes.resize(end + size);
    std::memcpy(bytes.data() + end, data, size);
}

} // namespace

std::string ResumeLog::pathFor(const std::string& output) {
    const fs::path path(output);
    return (path.parent_path() / fmt::format(".{}.crtc-resume", path.filename().string())).string();
}

bool ResumeLog::load(const std::string& path, std::string& error) {
    frames_.clear();
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return true; // nothing to continue
    char magic[sizeof kMagic];
    bool ok = std::fread(magic, 1, sizeof magic, file) == sizeof magic &&
              std::memcmp(magic, kMagic, sizeof magic) == 0;
    if (!ok) error = fmt::format("'{}' is not a resume log of this version of crtc", path);
    RecordHeader h{};
    while (ok && readRecordHeader(file, h)) {
        if (h.kind < kFrameBegun || h.kind > kFrameDone || h.count > kMaxTileFloats) {
            error = fmt::format("'{}' is damaged", path);
            ok = false;
            break;
        }
        std::vector<float> data(h.count);
        if (std::fread(data.data(), sizeof(float), data.size(), file) != data.size()) break; // torn
        LoggedFrame& frame = frames_[h.frame];
        if (h.kind == kFrameBegun)
            frame = LoggedFrame{h.value, false, {}};
        else if (h.kind == kTile)
            frame.tiles[static_cast<int>(h.value)] = std::move(data);
        else {
            frame.done = true;
            frame.tiles.clear();
        }
    }
    std::fclose(file);
    if (!ok) frames_.clear();
    return ok;
}

void ResumeLog::prepare(const std::string& path, bool keep, Clock::duration tileDelay,
                        std::function<void()> onStartedOrStopped) {
    path_ = path;
    tileDelay_ = tileDelay;
    onStartedOrStopped_ = std::move(onStartedOrStopped);
    if (keep) return;
    frames_.clear();
    // A log of an earlier render of this output is not continued into this one.
    std::error_code ignored;
    fs::remove(path_, ignored);
}

bool ResumeLog::start(std::string& error) {
    // The log is written whole from what is known, so that a torn record is gone.
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) {
        error = writeError();
        failed_ = true;
        return false;
    }
    pending_.clear();
    append(pending_, kMagic, sizeof kMagic);
    for (const auto& [number, frame] : frames_) {
        record(kFrameBegun, number, frame.sceneHash, nullptr, 0);
        for (const auto& [index, rgb] : frame.tiles)
            record(kTile, number, static_cast<uint64_t>(index), rgb.data(), rgb.size());
        if (frame.done) record(kFrameDone, number, 0, nullptr, 0);
    }
    lastSync_ = Clock::time_point();
    if (!writePending()) {
        error = writeError();
        ::close(fd_);
        fd_ = -1;
        failed_ = true;
        return false;
    }
    if (onStartedOrStopped_) onStartedOrStopped_();
    return true;
}

std::string ResumeLog::writeError() const {
    return fmt::format("cannot write the resume log '{}': {}", path_, std::strerror(errno));
}

ResumeLog::~ResumeLog() {
    if (started()) {
        writePending();
        ::close(fd_);
    }
}

void ResumeLog::record(uint8_t kind, int frame, uint64_t value, const float* data, size_t count) {
    if (!started()) return;
    const int32_t frame32 = frame;
    const uint64_t count64 = count;
    append(pending_, &kind, 1);
    append(pending_, &frame32, sizeof frame32);
    append(pending_, &value, sizeof value);
    append(pending_, &count64, sizeof count64);
    if (count > 0) append(pending_, data, count * sizeof(float));
}

/// Whether the file is there to take records: created now if need be.
bool ResumeLog::startOrGiveUp() {
    if (started()) return true;
    if (failed_ || path_.empty()) return false;
    std::string error;
    if (start(error)) return true;
    giveUp(error);
    return false;
}

void ResumeLog::giveUp(const std::string& why) {
    std::cerr << fmt::format("crtc: warning: {}; the render goes on, but cannot be continued if "
                             "it is interrupted\n",
                             lang::terminalSafe(why));
    failed_ = true;
    pending_ = {};
    remove();
    if (onStartedOrStopped_) onStartedOrStopped_();
}

bool ResumeLog::writePending() {
    const unsigned char* data = pending_.data();
    size_t left = pending_.size();
    while (left > 0) {
        const ssize_t written = ::write(fd_, data, left);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        data += written;
        left -= static_cast<size_t>(written);
    }
    pending_.clear();
    const Clock::time_point now = Clock::now();
    lastWrite_ = now;
    // Durable, so that a crash of the machine loses at most the last period's tiles.
    if (now - lastSync_ >= kWritePeriod) {
        lastSync_ = now;
        if (::fdatasync(fd_) != 0) return false;
    }
    return true;
}

void ResumeLog::writeSoon() {
    if (pending_.size() < kBlockBytes && Clock::now() - lastWrite_ < kWritePeriod) return;
    if (!writePending()) giveUp(writeError());
}

void ResumeLog::beginFrame(int frame, uint64_t sceneHash) {
    frameStart_ = Clock::now();
    LoggedFrame& logged = frames_[frame];
    if (logged.sceneHash == sceneHash && !logged.tiles.empty()) return; // continued: already logged
    logged = LoggedFrame{sceneHash, false, {}};
    record(kFrameBegun, frame, sceneHash, nullptr, 0);
}

void ResumeLog::addTile(int frame, const tracer::TileResult& tile) {
    if (Clock::now() - frameStart_ < tileDelay_) return;
    if (!startOrGiveUp()) return;
    record(kTile, frame, static_cast<uint64_t>(tile.index), tile.pixels.data(), tile.pixels.size());
    writeSoon();
}

void ResumeLog::frameDone(int frame) {
    frames_[frame].done = true;
    frames_[frame].tiles.clear();
    if (!startOrGiveUp()) return;
    record(kFrameDone, frame, 0, nullptr, 0);
    // The frame's file is in place: a crash of crtc from now on must not render it again.
    if (!writePending()) giveUp(writeError());
}

void ResumeLog::remove() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (path_.empty()) return;
    std::error_code ignored;
    fs::remove(path_, ignored);
}

} // namespace crt::crtc
