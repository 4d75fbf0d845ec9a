// crtc's resume log: when its file is created and written, and that what it wrote loads back.
#include "resume_log.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <thread>
#include <unistd.h>

using crt::crtc::ResumeLog;
using namespace crt::tracer;
namespace fs = std::filesystem;

namespace {

struct LogFolder {
    fs::path folder = fs::temp_directory_path() / ("crt_resume_log_" + std::to_string(getpid()));
    std::string path = (folder / ".out.png.crtc-resume").string();
    LogFolder() { fs::create_directories(folder); }
    ~LogFolder() { fs::remove_all(folder); }
    uintmax_t size() const { return fs::exists(path) ? fs::file_size(path) : 0; }
};

/// Tile `index` of 16 × 16 RGB pixels whose values tell which tile they belong to.
TileResult tile(int index, std::vector<float>& storage) {
    storage.assign(16 * 16 * 3, static_cast<float>(index) + 0.25f);
    return {{index * 16, 0, index * 16 + 16, 16}, index, 3, storage};
}

constexpr size_t kTileBytes = 16 * 16 * 3 * sizeof(float);

/// Sets `log` out to log at `path` (no earlier log kept) and logs `tiles` tiles of one frame.
void logFrame(ResumeLog& log, const std::string& path, ResumeLog::Clock::duration delay,
              int frame, uint64_t hash, int tiles, std::vector<float>& storage) {
    log.prepare(path, false, delay, nullptr);
    log.beginFrame(frame, hash);
    for (int i = 0; i < tiles; ++i) log.addTile(frame, tile(i, storage));
}

} // namespace

TEST_CASE("A frame's tiles are not logged before the delay, and no file is made",
          "[crtc][resume]") {
    LogFolder dir;
    std::vector<float> storage;
    {
        ResumeLog log;
        logFrame(log, dir.path, std::chrono::hours(1), 0, 42, 50, storage);
        CHECK_FALSE(log.started());
        log.remove(); // the render finished
    }
    CHECK_FALSE(fs::exists(dir.path));
}

TEST_CASE("A finished frame creates the log at once, before the delay", "[crtc][resume]") {
    LogFolder dir;
    std::vector<float> storage;
    int changes = 0;
    ResumeLog log;
    log.prepare(dir.path, false, std::chrono::hours(1), [&] { ++changes; });
    log.beginFrame(0, 42);
    log.addTile(0, tile(0, storage));
    log.frameDone(0);
    CHECK(log.started());
    CHECK(changes == 1);
    log.beginFrame(1, 43);

    ResumeLog read;
    std::string error;
    REQUIRE(read.load(dir.path, error));
    REQUIRE(read.frames().count(0) == 1);
    CHECK(read.frames().at(0).done);
    CHECK(read.frames().at(0).sceneHash == 42);
}

TEST_CASE("Tiles reach the file in blocks, within a second, and load back as they were",
          "[crtc][resume]") {
    LogFolder dir;
    std::vector<float> storage;
    {
        ResumeLog log;
        logFrame(log, dir.path, std::chrono::seconds(0), 3, 7, 20, storage);
        REQUIRE(log.started());
        // The first tile created the file; the others wait for the next block.
        CHECK(dir.size() < 2 * kTileBytes);
        std::this_thread::sleep_for(std::chrono::milliseconds(1100));
        log.addTile(3, tile(20, storage));
        CHECK(dir.size() > 21 * kTileBytes);
    }
    ResumeLog read;
    std::string error;
    REQUIRE(read.load(dir.path, error));
    const auto& tiles = read.frames().at(3).tiles;
    REQUIRE(tiles.size() == 21);
    for (const auto& [index, values] : tiles) {
        REQUIRE(values.size() == 16 * 16 * 3);
        CHECK(values.front() == static_cast<float>(index) + 0.25f);
        CHECK(values.back() == static_cast<float>(index) + 0.25f);
    }
}

TEST_CASE("A continued log is written again whole, with the tiles it had", "[crtc][resume]") {
    LogFolder dir;
    std::vector<float> storage;
    {
        ResumeLog log;
        logFrame(log, dir.path, std::chrono::seconds(0), 0, 9, 5, storage);
    }
    ResumeLog continued;
    std::string error;
    REQUIRE(continued.load(dir.path, error));
    REQUIRE(continued.frames().at(0).tiles.size() == 5);
    continued.prepare(dir.path, true, std::chrono::hours(1), nullptr);
    REQUIRE(continued.start(error));
    continued.beginFrame(0, 9); // the same frame: its tiles stay
    {
        ResumeLog read;
        REQUIRE(read.load(dir.path, error));
        CHECK(read.frames().at(0).tiles.size() == 5);
    }
    // A render without --continue discards an earlier log at once.
    ResumeLog fresh;
    fresh.prepare(dir.path, false, std::chrono::hours(1), nullptr);
    CHECK_FALSE(fs::exists(dir.path));
}

TEST_CASE("A log that cannot be written is given up, saying so", "[crtc][resume]") {
    LogFolder dir;
    std::vector<float> storage;
    int changes = 0;
    ResumeLog log;
    // In a folder that is not there: it cannot be created.
    log.prepare((dir.folder / "missing" / ".out.png.crtc-resume").string(), false,
                std::chrono::seconds(0), [&] { ++changes; });
    log.beginFrame(0, 1);
    log.addTile(0, tile(0, storage));
    CHECK_FALSE(log.started());
    CHECK(changes == 1);
    log.addTile(0, tile(1, storage)); // not tried again
    CHECK(changes == 1);
}
