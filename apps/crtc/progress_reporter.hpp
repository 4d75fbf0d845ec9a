// crtc's render progress on standard error, over all the frames of a run: a bar that fits the
// terminal's width, or a line per tenth when standard error is not a terminal.
#pragma once

#include <chrono>
#include <string>

namespace crt::crtc {

class ProgressReporter {
public:
    /// `frames`: how many frames the run renders; a quiet reporter prints nothing.
    ProgressReporter(bool quiet, int frames);

    /// The next frame begins; `label` names it in the progress ("frame 12 (3/10) ").
    void startFrame(std::string label);
    /// `done` of `total` tiles of the current frame are finished. Redraws a terminal's bar at
    /// most ten times a second, so that it can be called for every tile.
    void update(int done, int total);
    /// The current frame is finished (rendered or reused).
    void finishFrame();
    /// Clears the bar, if one is drawn: before anything else is printed.
    void clear();

private:
    using Clock = std::chrono::steady_clock;

    void draw(double fraction, double elapsed);

    bool quiet_;
    int frames_;
    int framesDone_ = 0;
    std::string label_;
    bool terminal_;
    size_t drawnLength_ = 0;
    int lastTenth_ = 0;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDrawn_{};
};

} // namespace crt::crtc
