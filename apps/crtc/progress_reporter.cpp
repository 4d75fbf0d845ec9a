// A progress bar or progress lines for crtc's renders.
#include "progress_reporter.hpp"

#include <fmt/format.h>

#include <iostream>
#include <unistd.h>

namespace crt::crtc {

ProgressReporter::ProgressReporter(bool quiet, std::string label)
    : quiet_(quiet), label_(std::move(label)), terminal_(isatty(STDERR_FILENO)) {}

void ProgressReporter::update(int done, int total) {
    if (quiet_ || total == 0) return;
    const Clock::time_point now = Clock::now();
    const double fraction = static_cast<double>(done) / total;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (terminal_) {
        if (done < total && now - lastDrawn_ < std::chrono::milliseconds(100)) return;
        lastDrawn_ = now;
        const int filled = static_cast<int>(fraction * 30);
        const std::string remaining =
            done > 0 ? fmt::format("{:.1f}s", elapsed / fraction - elapsed) : "?";
        std::cerr << fmt::format("\r{}[{:<30}] {:3.0f}%  elapsed {:.1f}s  remaining {}   ", label_,
                                 std::string(filled, '#'), fraction * 100, elapsed, remaining)
                  << std::flush;
        drawn_ = true;
        return;
    }
    const int tenth = static_cast<int>(fraction * 10);
    if (tenth > lastTenth_) {
        lastTenth_ = tenth;
        std::cerr << fmt::format("crtc: {}{}% ({:.1f}s)\n", label_, tenth * 10, elapsed);
    }
}

void ProgressReporter::finish() {
    if (drawn_) std::cerr << "\r" << std::string(80 + label_.size(), ' ') << "\r" << std::flush;
}

} // namespace crt::crtc
