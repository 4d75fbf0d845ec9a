// crtc's render progress.
#include "progress_reporter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <sys/ioctl.h>
#include <unistd.h>

namespace crt::crtc {

namespace {

/// The terminal's width in columns, 80 if it cannot be told.
int terminalColumns() {
    winsize size{};
    if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    return 80;
}

} // namespace

ProgressReporter::ProgressReporter(bool quiet, int frames)
    : quiet_(quiet), frames_(std::max(frames, 1)), terminal_(isatty(STDERR_FILENO)) {}

void ProgressReporter::startFrame(std::string label) {
    label_ = std::move(label);
}

void ProgressReporter::finishFrame() {
    ++framesDone_;
}

void ProgressReporter::update(int done, int total) {
    if (quiet_ || total == 0) return;
    const Clock::time_point now = Clock::now();
    const double fraction = (framesDone_ + static_cast<double>(done) / total) / frames_;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (terminal_) {
        if (done < total && now - lastDrawn_ < std::chrono::milliseconds(100)) return;
        lastDrawn_ = now;
        draw(fraction, elapsed);
        return;
    }
    const int tenth = static_cast<int>(fraction * 10);
    if (tenth > lastTenth_) {
        lastTenth_ = tenth;
        std::cerr << fmt::format("crtc: {}{}% ({:.1f}s)\n", label_, tenth * 10, elapsed);
    }
}

void ProgressReporter::draw(double fraction, double elapsed) {
    const std::string remaining =
        fraction > 0 ? fmt::format("{:.1f}s", elapsed / fraction - elapsed) : "?";
    const std::string figures =
        fmt::format(" {:3.0f}%  elapsed {:.1f}s  remaining {}", fraction * 100, elapsed, remaining);
    // The line stays one column short of the width: a full line would wrap on some terminals.
    const int columns = terminalColumns();
    const int room = columns - 1 - static_cast<int>(label_.size() + figures.size());
    std::string line = label_;
    if (room >= 12) {
        const int barWidth = std::min(room - 2, 40);
        const int filled = static_cast<int>(fraction * barWidth);
        line += fmt::format("[{:<{}}]", std::string(filled, '#'), barWidth);
    }
    line += figures;
    line.resize(std::min(line.size(), static_cast<size_t>(std::max(columns - 1, 1))));
    const size_t length = line.size();
    if (length < drawnLength_) line.append(drawnLength_ - length, ' ');
    std::cerr << "\r" << line << std::flush;
    drawnLength_ = length;
}

void ProgressReporter::clear() {
    if (drawnLength_ == 0) return;
    std::cerr << "\r" << std::string(drawnLength_, ' ') << "\r" << std::flush;
    drawnLength_ = 0;
}

} // namespace crt::crtc
