// crtc's render progress on standard error: a bar on a terminal, a line per tenth otherwise.
#pragma once

#include <chrono>
#include <string>

namespace crt::crtc {

class ProgressReporter {
public:
    /// `label` starts every line ("frame 2/24 "); a quiet reporter prints nothing.
    ProgressReporter(bool quiet, std::string label);

    /// `done` of `total` tiles are finished. Redraws a terminal's bar at most ten times a
    /// second, so that it can be called for every tile.
    void update(int done, int total);
    /// Clears the bar, if one was drawn.
    void finish();

private:
    using Clock = std::chrono::steady_clock;

    bool quiet_;
    std::string label_;
    bool terminal_;
    bool drawn_ = false;
    int lastTenth_ = 0;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDrawn_{};
};

} // namespace crt::crtc
