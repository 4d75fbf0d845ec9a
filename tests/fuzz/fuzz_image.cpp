// libFuzzer target for reading images through the image module (OpenImageIO, loaded on first
// use): arbitrary bytes as an image file, which readImage and describeImage open by path.
#include "tracer/image_io/image_io.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
namespace image_io = crt::tracer::image_io;

/// The image size limit, as crtc's --max-image-pixels (256 × 256): one input stays fast, and
/// memory stays far below libFuzzer's limit (a 4-byte header may claim 2^31 × 2^31 pixels).
/// A decoder runs the same code for every row and tile, so a larger image only multiplies the
/// time of one input.
constexpr uint64_t kMaxPixels = uint64_t{1} << 16;

/// The file every input is written to: one per process (a campaign may run several), in the
/// system's temporary directory, removed at exit. Never destroyed, so the exit handler can use it.
const std::string& inputPath() {
    static const std::string* const path = [] {
        const fs::path dir = fs::temp_directory_path() / ("crt-fuzz-image-" + std::to_string(getpid()));
        fs::create_directories(dir);
        // No extension: OpenImageIO recognises the format by the file's contents.
        auto* file = new std::string((dir / "input").string());
        std::atexit([] { std::error_code ignored; fs::remove_all(fs::path(inputPath()).parent_path(), ignored); });
        return file;
    }();
    return *path;
}

bool writeInput(const uint8_t* data, size_t size) {
    std::FILE* file = std::fopen(inputPath().c_str(), "wb");
    if (!file) return false;
    const bool written = std::fwrite(data, 1, size, file) == size;
    return std::fclose(file) == 0 && written;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // The build tree's module, unless the environment names another one.
    setenv("CRT_IMAGE_IO_MODULE", CRT_IMAGE_IO_MODULE_PATH, 0);
    std::string error;
    if (!image_io::ensureLoaded(error)) {
        std::fprintf(stderr, "fuzz_image: %s\n", error.c_str());
        std::exit(1);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!writeInput(data, size)) std::abort();
    std::string error;
    std::optional<image_io::ImageInfo> info = image_io::describeImage(inputPath(), error, kMaxPixels);
    if (!info) {
        if (error.empty()) std::abort(); // a refusal always says why
        return 0;
    }
    bool eightBit = false;
    std::optional<image_io::ImageBuffer> image = image_io::readImage(inputPath(), error, &eightBit, kMaxPixels);
    if (!image) {
        if (error.empty()) std::abort();
        return 0;
    }
    // What readImage promises: three channels (four with alpha), every pixel present.
    if ((image->channels != 3 && image->channels != 4) || image->width < 1 || image->height < 1 ||
        image->pixels.size() != size_t(image->width) * size_t(image->height) * image->channels)
        std::abort();
    return 0;
}
