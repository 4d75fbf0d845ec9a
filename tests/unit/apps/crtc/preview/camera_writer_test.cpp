// Writing the preview's camera into scripts of several shapes.
#include "preview/camera_writer.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace crt;
using namespace crt::crtc::preview;

namespace {

scene::CameraDesc newCamera() {
    scene::CameraDesc c;
    c.position = {1.25, 2.5, -6.0};
    c.pointing = {0.0, 1.0, 0.0};
    c.fov = 50;
    return c;
}

/// The camera the script evaluates to.
scene::CameraDesc evaluatedCamera(const std::string& text) {
    lang::Compilation c = lang::compile("scene.crt", text, {});
    REQUIRE(c.scene);
    return c.scene->camera;
}

const char* kLights = "    lights -> [PointLight { origin -> vec3(0, 5, 0) color -> rgb(1, 1, 1) }]\n";

} // namespace

TEST_CASE("the camera literal names the attributes that differ from their defaults", "[preview]") {
    scene::CameraDesc c = newCamera();
    CHECK(cameraLiteral(c) == "Camera { position -> vec3(1.25, 2.5, -6.0) pointing -> vec3(0.0, 1.0, 0.0) fov -> 50.0 }");
    c.roll = 10;
    c.up = {0, 0, 1};
    c.position.x = 1.0 / 3;
    CHECK(cameraLiteral(c) == "Camera { position -> vec3(0.333333, 2.5, -6.0) pointing -> vec3(0.0, 1.0, 0.0) "
                              "fov -> 50.0 up -> vec3(0.0, 0.0, 1.0) roll -> 10.0 }");
    CHECK(cameraLiteral(newCamera(), true) ==
          "Camera {\nposition -> vec3(1.25, 2.5, -6.0)\npointing -> vec3(0.0, 1.0, 0.0)\nfov -> 50.0\n}");
}

TEST_CASE("a camera literal on one line is replaced, and nothing else changes", "[preview]") {
    const std::string script = std::string("-- a scene\nSettings {\n") +
                               "    camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }\n" +
                               kLights + "}\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }\n";
    const CameraEdit edit = placeCamera("scene.crt", script, newCamera(), {});
    REQUIRE(edit.ok);
    CHECK(edit.message == "replaced the camera at scene.crt:3:15");
    CHECK(edit.text == std::string("-- a scene\nSettings {\n") +
                           "    camera -> Camera { position -> vec3(1.25, 2.5, -6.0) pointing -> vec3(0.0, 1.0, 0.0) "
                           "fov -> 50.0 }\n" +
                           kLights + "}\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }\n");
    const scene::CameraDesc evaluated = evaluatedCamera(edit.text);
    CHECK(evaluated.position == newCamera().position);
    CHECK(evaluated.fov == 50);
}

TEST_CASE("a camera literal over several lines is replaced by one indented the same way", "[preview]") {
    const std::string script = std::string("Settings {\n    camera -> Camera {\n        position -> vec3(0, 1, -5)\n") +
                               "        pointing -> vec3(0, 0, 0)\n    }\n" + kLights + "}\n";
    const CameraEdit edit = placeCamera("scene.crt", script, newCamera(), {});
    REQUIRE(edit.ok);
    CHECK(edit.text == std::string("Settings {\n    camera -> Camera {\n        position -> vec3(1.25, 2.5, -6.0)\n") +
                           "        pointing -> vec3(0.0, 1.0, 0.0)\n        fov -> 50.0\n    }\n" + kLights + "}\n");
    CHECK(evaluatedCamera(edit.text).position == newCamera().position);
}

TEST_CASE("a Settings block without a camera gets one", "[preview]") {
    const std::string script = std::string("Settings {\n") + kLights + "}\n";
    const CameraEdit edit = placeCamera("scene.crt", script, newCamera(), {});
    REQUIRE(edit.ok);
    CHECK(edit.message == "added the camera to the Settings block");
    CHECK(evaluatedCamera(edit.text).pointing == newCamera().pointing);
}

TEST_CASE("a camera held by a variable or made by a macro is left for the user to paste", "[preview]") {
    const std::string byName = std::string("cam = Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }\n") +
                               "Settings {\n    camera -> cam\n" + kLights + "}\n";
    CameraEdit edit = placeCamera("scene.crt", byName, newCamera(), {});
    CHECK_FALSE(edit.ok);
    CHECK(edit.message == "the camera is set by 'cam' at scene.crt:3:15: copy the camera and paste it where that "
                          "is defined");

    const std::string byMacro = std::string("eye = Macro(d) { Camera { position -> vec3(0, 1, -d) pointing -> vec3(0, 0, 0) } }\n") +
                                "Settings {\n    camera -> eye(5)\n" + kLights + "}\n";
    edit = placeCamera("scene.crt", byMacro, newCamera(), {});
    CHECK_FALSE(edit.ok);
    CHECK(edit.message.starts_with("the camera is set by 'eye(5)' at scene.crt:3:15"));
}

TEST_CASE("scripts the camera cannot be placed in are refused with a reason", "[preview]") {
    CHECK(placeCamera("scene.crt", "Scene { }\n", newCamera(), {}).message ==
          "the script has no Settings block: paste the camera into one");
    CHECK(placeCamera("scene.crt", "Settings { width -> }\n", newCamera(), {}).message ==
          "the script has syntax errors: fix them before writing the camera into it");
    CHECK_FALSE(placeCamera("scene.crt", "Settings { }\nSettings { }\n", newCamera(), {}).ok);
}

TEST_CASE("replaceFile swaps the whole file and leaves no temporary behind", "[preview]") {
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("crtc_preview_writer_test_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::string path = (folder / "scene.crt").string();
    std::ofstream(path) << "old";
    std::string error;
    REQUIRE(replaceFile(path, "new text", error));
    std::ifstream in(path);
    CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == "new text");
    CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);
    CHECK_FALSE(replaceFile((folder / "missing" / "scene.crt").string(), "x", error));
    CHECK_FALSE(error.empty());
    fs::remove_all(folder);
}
