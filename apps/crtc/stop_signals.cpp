// Signal handlers that leave no temporary file behind.
//
// A handler may call only async-signal-safe functions, so everything it needs is ready
// before the signal: the temporaries are listed in image_io's fixed table, and the note is
// written into one of two buffers while the handler would read the other.
#include "stop_signals.hpp"

#include "tracer/image_io/temporary_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>

namespace crt::crtc {
namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

char notes[2][1024] = {"crtc: interrupted\n", ""};
std::atomic<int> currentNote{0};
bool terminal = false; ///< standard error is a terminal, where a progress bar may be drawn

extern "C" void onStopSignal(int signal) {
    tracer::image_io::removeAllTemporaries();
    const char* note = notes[currentNote.load()];
    ssize_t ignored = terminal ? ::write(STDERR_FILENO, "\n", 1) : 0;
    ignored = ::write(STDERR_FILENO, note, std::strlen(note));
    (void)ignored;
    // Ended by the signal itself, as if there were no handler; a SIGCONT handled as a stop
    // (its default would let the process go on, to print this note again at the next signal)
    // as by SIGTERM.
    const int ending = signal == SIGCONT ? SIGTERM : signal;
    std::signal(ending, SIG_DFL);
    std::raise(ending);
}

extern "C" void onExit() {
    if (tracer::image_io::removeAllTemporaries() == 0) return;
    // A library ended the program while an image was being written: it is not complete.
    static constexpr char kNote[] = "crtc: the image library stopped while writing; no image written\n";
    ssize_t ignored = ::write(STDERR_FILENO, kNote, sizeof kNote - 1);
    (void)ignored;
    ::_exit(2);
}

} // namespace

void installExitCleanup() { std::atexit(onExit); }

void installStopHandlers() {
    terminal = ::isatty(STDERR_FILENO);
    for (int signal : kStopSignals) {
        struct sigaction action {};
        action.sa_handler = onStopSignal;
        sigemptyset(&action.sa_mask);
        // One handler at a time: a second signal waits until the first has ended crtc.
        for (int other : kStopSignals) sigaddset(&action.sa_mask, other);
        sigaction(signal, &action, nullptr);
    }
}

void setStopNote(const std::string& line) {
    const int next = 1 - currentNote.load();
    const std::size_t size = std::min(line.size(), sizeof notes[next] - 1);
    std::memcpy(notes[next], line.data(), size);
    notes[next][size] = '\0';
    currentNote.store(next);
}

} // namespace crt::crtc
