// Image I/O without the module: linking costs nothing, and a missing or broken module is an error.
//
// This binary must never load OpenImageIO itself (catch_discover_tests runs it once per test
// case, and each would pay OpenImageIO's slow load), so the load failures are provoked in
// forked children.
#include "tracer/image_io/image_io.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

using namespace crt::tracer::image_io;
namespace fs = std::filesystem;

namespace {

bool openImageIoMapped() {
    std::ifstream maps("/proc/self/maps");
    const std::string text{std::istreambuf_iterator<char>(maps), std::istreambuf_iterator<char>()};
    return text.find("libOpenImageIO") != std::string::npos;
}

// Runs readImage in a child whose CRT_IMAGE_IO_MODULE is `module` (unset when empty), and
// returns its error (or "ok" / "crashed"), so that this process's one-time load stays untouched.
std::string readErrorWithModule(const std::string& module, const std::string& image) {
    int pipeEnds[2];
    REQUIRE(pipe(pipeEnds) == 0);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        close(pipeEnds[0]);
        if (module.empty())
            unsetenv("CRT_IMAGE_IO_MODULE");
        else
            setenv("CRT_IMAGE_IO_MODULE", module.c_str(), 1);
        std::string error;
        const std::string result = readImage(image, error) ? "ok" : error;
        const ssize_t written = write(pipeEnds[1], result.data(), result.size());
        _exit(written == ssize_t(result.size()) ? 0 : 1);
    }
    close(pipeEnds[1]);
    std::string result;
    char chunk[512];
    for (ssize_t n; (n = read(pipeEnds[0], chunk, sizeof chunk)) > 0;) result.append(chunk, n);
    close(pipeEnds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status)) return "crashed";
    return result;
}

struct ScratchFile {
    fs::path path;
    explicit ScratchFile(const std::string& name, const std::string& content)
        : path(fs::temp_directory_path() / (name + "." + std::to_string(getpid()))) {
        std::ofstream(path) << content;
    }
    ~ScratchFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
};

} // namespace

TEST_CASE("linking crt_image_io does not load OpenImageIO", "[image_io][loader]") {
    // Calls that need no pixels must not load the module either.
    CHECK(isSupportedOutput("a.png"));
    std::string error;
    CHECK_FALSE(writeImage("out.xyz", ImageBuffer{1, 1, 3, {0, 0, 0}}, {}, error));
    CHECK_FALSE(openImageIoMapped());
}

TEST_CASE("output formats are chosen by extension", "[image_io][loader]") {
    for (const char* name : {"a.png", "a.PNG", "dir.x/a.jpg", "a.jpeg", "a.tif", "a.tiff", "a.exr",
                             "a.hdr", "a.gif", "/abs/path/A.Exr"}) {
        INFO(name);
        CHECK(isSupportedOutput(name));
    }
    for (const char* name : {"a", "a.", "a.bmp", "a.png.txt", ".png", "dir.png/", "a.xyz"}) {
        INFO(name);
        CHECK_FALSE(isSupportedOutput(name));
    }
}

TEST_CASE("an unknown extension is rejected with the supported list", "[image_io][loader]") {
    std::string error;
    CHECK_FALSE(writeImage("picture.bmp", ImageBuffer{1, 1, 3, {0, 0, 0}}, {}, error));
    CHECK_THAT(error, Catch::Contains("picture.bmp") && Catch::Contains(".bmp") &&
                          Catch::Contains(".png") && Catch::Contains(".exr"));
    error.clear();
    CHECK_FALSE(writeImage("picture", ImageBuffer{1, 1, 3, {0, 0, 0}}, {}, error));
    CHECK_THAT(error, Catch::Contains("supported are"));
    CHECK_FALSE(fs::exists("picture.bmp"));
    CHECK_FALSE(fs::exists("picture"));
}

TEST_CASE("a missing module is an error naming it, not a crash", "[image_io][loader]") {
    const ScratchFile image("crt_image_io_input.png", "not really a png");
    const std::string missing = "/nonexistent/crt_image_io_oiio.so";
    const std::string error = readErrorWithModule(missing, image.path.string());
    CHECK_THAT(error, Catch::Contains(missing) && Catch::Contains("does not exist") &&
                          Catch::Contains(image.path.string()));
}

TEST_CASE("a file that is not a module is an error, not a crash", "[image_io][loader]") {
    const ScratchFile image("crt_image_io_input.png", "not really a png");
    const ScratchFile notModule("crt_image_io_fake.so", "not an ELF file");
    const std::string error = readErrorWithModule(notModule.path.string(), image.path.string());
    CHECK_THAT(error, Catch::Contains("cannot load the image module") &&
                          Catch::Contains(notModule.path.string()));
}

TEST_CASE("a shared library without the entry point is refused", "[image_io][loader]") {
    const ScratchFile image("crt_image_io_input.png", "not really a png");
    // Any shared library will do; the C library is always there.
    std::string libc;
    {
        std::ifstream maps("/proc/self/maps");
        for (std::string line; std::getline(maps, line) && libc.empty();) {
            const auto at = line.find('/');
            if (at != std::string::npos && line.find("/libc.so") != std::string::npos)
                libc = line.substr(at);
        }
    }
    REQUIRE_FALSE(libc.empty());
    const std::string error = readErrorWithModule(libc, image.path.string());
    CHECK_THAT(error, Catch::Contains("has no entry point"));
}

TEST_CASE("without the variable, the module is looked for beside the executable",
          "[image_io][loader]") {
    // The build puts the module beside crtc, not beside this test, so the search fails here
    // and its message shows where it looked.
    const ScratchFile image("crt_image_io_input.png", "not really a png");
    const fs::path exeDir = fs::read_symlink("/proc/self/exe").parent_path();
    const std::string error = readErrorWithModule("", image.path.string());
    CHECK_THAT(error, Catch::Contains("was not found") &&
                          Catch::Contains((exeDir / "crt_image_io_oiio.so").string()) &&
                          Catch::Contains(
                              (exeDir.parent_path() / "lib/crt/crt_image_io_oiio.so").string()) &&
                          Catch::Contains("CRT_IMAGE_IO_MODULE"));
}
