// The resume log: a header, then records appended as the render goes:
//   kind (1 byte: frame begun, tile, frame done), frame (int32), value (uint64: the scene's
//   hash, or the tile's index), count (uint64) and `count` floats (a tile's RGB).
// Numbers are in the machine's byte order: a log is continued where it was written.
#include "resume_log.hpp"

#include <fmt/format.h>

#include <cstring>
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

bool ResumeLog::open(const std::string& path, bool keep, std::string& error) {
    path_ = path;
    if (!keep) frames_.clear();
    // The log is written again whole from what is known, so that a torn record is gone.
    file_ = std::fopen(path.c_str(), "wb");
    if (!file_) {
        error = fmt::format("cannot write the resume log '{}': {}", path, std::strerror(errno));
        return false;
    }
    if (std::fwrite(kMagic, 1, sizeof kMagic, file_) != sizeof kMagic || !flush()) {
        error = fmt::format("cannot write the resume log '{}': {}", path, std::strerror(errno));
        return false;
    }
    for (const auto& [number, frame] : frames_) {
        record(kFrameBegun, number, frame.sceneHash, nullptr, 0);
        for (const auto& [index, rgb] : frame.tiles)
            record(kTile, number, static_cast<uint64_t>(index), rgb.data(), rgb.size());
        if (frame.done) record(kFrameDone, number, 0, nullptr, 0);
    }
    return flush();
}

ResumeLog::~ResumeLog() {
    if (file_) {
        flush();
        std::fclose(file_);
    }
}

void ResumeLog::record(uint8_t kind, int frame, uint64_t value, const float* data, size_t count) {
    if (!file_ || failed_) return;
    const int32_t frame32 = frame;
    const uint64_t count64 = count;
    bool ok = std::fwrite(&kind, 1, 1, file_) == 1 &&
              std::fwrite(&frame32, sizeof frame32, 1, file_) == 1 &&
              std::fwrite(&value, sizeof value, 1, file_) == 1 &&
              std::fwrite(&count64, sizeof count64, 1, file_) == 1;
    if (ok && count > 0) ok = std::fwrite(data, sizeof(float), count, file_) == count;
    if (!ok) {
        failed_ = true;
        std::cerr << fmt::format(
            "crtc: warning: cannot write the resume log '{}': {}; the render goes on, but "
            "cannot be continued if it is interrupted\n",
            path_, std::strerror(errno));
    }
}

void ResumeLog::beginFrame(int frame, uint64_t sceneHash) {
    LoggedFrame& logged = frames_[frame];
    if (logged.sceneHash == sceneHash && !logged.tiles.empty()) return; // continued: already logged
    logged = LoggedFrame{sceneHash, false, {}};
    record(kFrameBegun, frame, sceneHash, nullptr, 0);
}

void ResumeLog::addTile(int frame, const tracer::TileResult& tile) {
    record(kTile, frame, static_cast<uint64_t>(tile.index), tile.pixels.data(), tile.pixels.size());
    flushSoon();
}

void ResumeLog::frameDone(int frame) {
    frames_[frame].done = true;
    frames_[frame].tiles.clear();
    record(kFrameDone, frame, 0, nullptr, 0);
    flush();
}

void ResumeLog::flushSoon() {
    if (std::chrono::steady_clock::now() - lastFlush_ >= std::chrono::seconds(1)) flush();
}

bool ResumeLog::flush() {
    lastFlush_ = std::chrono::steady_clock::now();
    if (!file_ || failed_) return !failed_;
    // Durable, so that a crash of the machine loses at most the last second of tiles.
    return std::fflush(file_) == 0 && fdatasync(fileno(file_)) == 0;
}

void ResumeLog::remove() {
    if (file_) std::fclose(file_);
    file_ = nullptr;
    std::error_code ignored;
    fs::remove(path_, ignored);
}

} // namespace crt::crtc
