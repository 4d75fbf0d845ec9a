// Compares a render with its reference image at the spec's tolerance (§6: at most 2/255 per
// channel on 99.5% of pixels) and reports the largest difference. With --rmse the verdict is
// instead the root mean square difference over the colour channels, in 8-bit codes (POV-Ray
// twins).
//
// usage: render_compare REFERENCE IMAGE [--tolerance CODES] [--fraction F] [--rmse CODES]
// Exit status: 0 identical or within tolerance, 1 outside it, 2 unreadable or of another size.
// The first word of the report line is IDENTICAL, WITHIN or DIFFERENT, for scripts.
#include "tracer/image_io/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace image_io = crt::tracer::image_io;

namespace {

/// 8-bit files read back as code / 255; compare codes, which is what the tolerance counts.
int code(float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

int usage() {
    std::fprintf(stderr, "usage: render_compare REFERENCE IMAGE [--tolerance CODES] [--fraction F] "
                         "[--rmse CODES]\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    std::string referencePath = argv[1], imagePath = argv[2];
    int tolerance = 2;         // per channel, in 8-bit codes
    double fraction = 0.995;   // of pixels that must be within the tolerance
    double rmseLimit = -1;     // in codes; < 0: judge by tolerance and fraction
    for (int i = 3; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--tolerance" && i + 1 < argc) tolerance = std::atoi(argv[++i]);
        else if (arg == "--fraction" && i + 1 < argc) fraction = std::atof(argv[++i]);
        else if (arg == "--rmse" && i + 1 < argc)
            rmseLimit = std::atof(argv[++i]);
        else return usage();
    }

    std::string error;
    auto reference = image_io::readImage(referencePath, error);
    if (!reference) {
        std::fprintf(stderr, "render_compare: %s\n", error.c_str());
        return 2;
    }
    auto image = image_io::readImage(imagePath, error);
    if (!image) {
        std::fprintf(stderr, "render_compare: %s\n", error.c_str());
        return 2;
    }
    if (reference->width != image->width || reference->height != image->height) {
        std::printf("DIFFERENT: size %dx%d, reference %dx%d\n", image->width, image->height, reference->width,
                    reference->height);
        return 1;
    }

    size_t pixels = static_cast<size_t>(image->width) * image->height;
    int largest = 0;
    size_t over = 0, changed = 0;
    int worstX = 0, worstY = 0;
    double squares = 0;
    for (size_t p = 0; p < pixels; ++p) {
        int d = 0;
        for (int c = 0; c < 3; ++c) {
            int difference = std::abs(code(image->pixels[image->channels * p + c]) -
                                      code(reference->pixels[reference->channels * p + c]));
            d = std::max(d, difference);
            squares += static_cast<double>(difference) * difference;
        }
        if (d > largest) {
            largest = d;
            worstX = static_cast<int>(p % image->width);
            worstY = static_cast<int>(p / image->width);
        }
        changed += d > 0;
        over += d > tolerance;
    }
    double overShare = static_cast<double>(over) / pixels;
    double rmse = std::sqrt(squares / (3.0 * static_cast<double>(pixels)));
    bool pass = rmseLimit >= 0 ? rmse <= rmseLimit : overShare <= 1 - fraction + 1e-12;
    const char* verdict = changed == 0 ? "IDENTICAL" : pass ? "WITHIN" : "DIFFERENT";
    std::string where = largest > 0 ? " (at " + std::to_string(worstX) + "," + std::to_string(worstY) + ")" : "";
    std::printf("%s: max difference %d/255%s; %zu of %zu pixels differ, %zu (%.3f%%) by more than %d/255 "
                "(allowed %.3f%%)\n",
                verdict, largest, where.c_str(), changed, pixels, over, 100 * overShare, tolerance,
                100 * (1 - fraction));
    if (rmseLimit >= 0) std::printf("RMSE %.3f/255 (allowed %.3f/255)\n", rmse, rmseLimit);
    return pass ? 0 : 1;
}
