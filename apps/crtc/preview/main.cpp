// crtc-preview: the program behind `crtc --preview` (docs/preview.md). crtc reads its command
// line, then runs this program in its own place with the same arguments (preview_launch.hpp);
// it reads them again with the same parser, so both agree on every option.
#include "include_search.hpp"
#include "options.hpp"
#include "preview/preview_command.hpp"
#include "stop_signals.hpp"

#include <iostream>
#include <new>

using namespace crt;

namespace {

int run(int argc, char** argv) {
    crtc::ParsedOptions parsed = crtc::parseOptions(argc, argv);
    if (!parsed.options) {
        (parsed.status == 0 ? std::cout : std::cerr)
            << parsed.message << (parsed.message.ends_with('\n') ? "" : "\n");
        return parsed.status;
    }
    crtc::Options& options = *parsed.options;
    if (options.mode != crtc::Mode::Preview) {
        std::cerr << "crtc-preview: run it as crtc --preview\n";
        return 2;
    }
    crtc::installStopHandlers();
    crtc::installExitCleanup();
    options.eval.includes.stdlibDir = lang::defaultStdlibDir();
    return crtc::previewCommand(options);
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "crtc: out of memory\n";
        return 2;
    }
}
