// The preview session's render loop: passes, and the cancelling of a render that an edit
// made useless.
#include "preview/session.hpp"
#include "preview/server.hpp"

#include <catch2/catch.hpp>

#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <unistd.h>

using namespace crt;
using namespace crt::crtc::preview;
namespace fs = std::filesystem;

namespace {

/// The events a session published, for the test to wait on.
class Recorder {
public:
    Publish publisher() {
        return [this](const std::string& name, const nlohmann::json& data) {
            std::lock_guard lock(mutex_);
            events_.emplace_back(name, data);
            changed_.notify_all();
        };
    }
    /// Waits (up to a minute) for an event that `match` accepts; returns it.
    nlohmann::json waitFor(const std::string& name, const std::function<bool(const nlohmann::json&)>& match) {
        std::unique_lock lock(mutex_);
        nlohmann::json found;
        const bool seen = changed_.wait_for(lock, std::chrono::minutes(1), [&] {
            for (const auto& [n, data] : events_)
                if (n == name && match(data)) {
                    found = data;
                    return true;
                }
            return false;
        });
        REQUIRE(seen);
        return found;
    }
    std::vector<std::pair<std::string, nlohmann::json>> events() {
        std::lock_guard lock(mutex_);
        return events_;
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<std::pair<std::string, nlohmann::json>> events_;
};

std::string sceneText(int width, int height, int supersampling, const char* color) {
    return "Settings {\n    width -> " + std::to_string(width) + "\n    height -> " + std::to_string(height) +
           "\n    supersampling -> " + std::to_string(supersampling) +
           "\n    camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }\n"
           "    lights -> [PointLight { origin -> vec3(2, 5, -3) color -> rgb(1, 1, 1) }]\n"
           "    background -> " + color + "\n}\n"
           "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> Material { color -> rgb(1, 0.5, 0) "
           "reflectivity -> 0.3 } } }\n";
}

/// A script in a folder of its own: test cases run in parallel processes.
struct ScriptFile {
    fs::path folder;
    std::string path;

    /// `name`: the folder's name before the process id.
    explicit ScriptFile(const std::string& text, const std::string& name = "crtc_preview_session_test_")
        : folder(fs::temp_directory_path() / (name + std::to_string(::getpid()))),
          path((folder / "scene.crt").string()) {
        fs::remove_all(folder);
        fs::create_directories(folder);
        write(text);
    }
    ~ScriptFile() { fs::remove_all(folder); }
    void write(const std::string& text) const { std::ofstream(path, std::ios::trunc) << text; }
};

crtc::Options optionsFor(const std::string& script) {
    crtc::Options options;
    options.script = script;
    options.threads = 2;
    return options;
}

} // namespace

TEST_CASE("the session refines an image pass by pass to the script's quality", "[preview]") {
    ScriptFile script(sceneText(64, 48, 2, "rgb(0.2, 0.3, 0.4)"));
    Recorder recorder;
    Session session(optionsFor(script.path), recorder.publisher());
    session.start();
    recorder.waitFor("frame", [](const nlohmann::json& f) { return f["pass"] == f["passes"]; });
    std::vector<int> widths;
    for (const auto& [name, data] : recorder.events())
        if (name == "frame") widths.push_back(data["width"]);
    CHECK(widths == std::vector<int>{8, 32, 64, 64});
    const std::shared_ptr<const FrameImage> image = session.latestImage();
    REQUIRE(image);
    CHECK(image->width == 64);
    CHECK(image->png.size() > 8);
    CHECK(session.state()["errors"] == false);
}

TEST_CASE("an edit during a long render cancels it and renders the new script", "[preview]") {
    // Slow: hundreds of tiles of 64 samples a pixel, so the edit lands while it renders.
    ScriptFile script(sceneText(1600, 1200, 8, "rgb(0.2, 0.3, 0.4)"));
    Recorder recorder;
    Session session(optionsFor(script.path), recorder.publisher());
    session.start();
    // The full-size pass of the slow script is under way.
    recorder.waitFor("progress", [](const nlohmann::json& p) { return p["pass"] == 4 && p["done"] > 0; });
    script.write(sceneText(40, 30, 1, "rgb(1, 0, 0)"));
    session.reload();
    recorder.waitFor("frame", [](const nlohmann::json& f) { return f["width"] == 40 && f["pass"] == f["passes"]; });
    // The slow script's last pass never finished: its image was not worth finishing.
    for (const auto& [name, data] : recorder.events()) {
        if (name == "frame") CHECK_FALSE((data["width"] == 1600 && data["pass"] == 4));
        if (name == "progress" && data["tiles"] == 7500) CHECK(data["done"] < 7500);
    }
}

TEST_CASE("a script with errors keeps the last good scene and reports file:line:col", "[preview]") {
    ScriptFile script(sceneText(32, 24, 1, "rgb(0.2, 0.3, 0.4)"));
    Recorder recorder;
    Session session(optionsFor(script.path), recorder.publisher());
    session.start();
    recorder.waitFor("frame", [](const nlohmann::json& f) { return f["pass"] == f["passes"]; });
    script.write("Settings {\n    width -> \n}\n");
    session.reload();
    const nlohmann::json report = recorder.waitFor("diagnostics", [](const nlohmann::json& d) { return d["errors"] == true; });
    CHECK(report["diagnostics"][0].get<std::string>().find("scene.crt:3:1: error:") != std::string::npos);
    CHECK(session.state()["width"] == 32); // the last good scene
    CHECK(session.pick(0.5, 0.5)["kind"] == "Sphere");
}

TEST_CASE("the page gets JSON when the script's path is not UTF-8", "[preview]") {
    // Linux paths are bytes; "\xE9" is Latin-1's "é".
    ScriptFile script(sceneText(32, 24, 1, "rgb(0.2, 0.3, 0.4)"), "crtc_preview_caf\xE9_");
    Recorder recorder;
    Session session(optionsFor(script.path), recorder.publisher());
    session.start();
    recorder.waitFor("frame", [](const nlohmann::json& f) { return f["pass"] == f["passes"]; });
    const nlohmann::json state = nlohmann::json::parse(pageJson(session.state()));
    CHECK(state["script"].get<std::string>().find("crtc_preview_caf\xEF\xBF\xBD_") != std::string::npos);
    const nlohmann::json picked = nlohmann::json::parse(pageJson(session.pick(0.5, 0.5)));
    CHECK(picked["location"].get<std::string>().find("caf\xEF\xBF\xBD_") != std::string::npos);
}
