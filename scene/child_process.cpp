// Runs a piece of work in a child process (see child_process.hpp).
#include "scene/child_process.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace crt::scene {

namespace {

bool writeAll(int fd, const std::string& bytes) {
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

/// Reads exactly `size` bytes; false when the pipe ends before.
bool readAll(int fd, void* to, size_t size) {
    for (size_t done = 0; done < size;) {
        const ssize_t n = ::read(fd, static_cast<char*>(to) + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

} // namespace

std::optional<std::string> inChildProcess(const std::function<std::string()>& work,
                                          uint64_t maxBytes, std::string& why) {
    int pipeEnds[2];
    // Close-on-exec: a process another thread starts meanwhile must not hold the write end.
    if (::pipe2(pipeEnds, O_CLOEXEC) != 0) {
        why = fmt::format("cannot make a pipe: {}", std::strerror(errno));
        return std::nullopt;
    }
    const pid_t child = ::fork();
    if (child < 0) {
        why = fmt::format("cannot start a process: {}", std::strerror(errno));
        ::close(pipeEnds[0]);
        ::close(pipeEnds[1]);
        return std::nullopt;
    }
    if (child == 0) {
        ::close(pipeEnds[0]);
        const std::string bytes = work();
        // Its length first, so that the parent takes them in one piece of memory.
        const uint64_t length = bytes.size();
        const bool written =
            writeAll(pipeEnds[1],
                     std::string(reinterpret_cast<const char*>(&length), sizeof length)) &&
            writeAll(pipeEnds[1], bytes);
        ::_exit(written ? 0 : 1);
    }
    ::close(pipeEnds[1]);
    uint64_t length = 0;
    std::string bytes;
    const bool told = readAll(pipeEnds[0], &length, sizeof length);
    const bool tooLong = told && length > maxBytes;
    bool complete = told && !tooLong;
    if (complete) {
        bytes.resize(length);
        complete = readAll(pipeEnds[0], bytes.data(), length);
    }
    ::close(pipeEnds[0]);
    if (tooLong) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (tooLong) {
        why = fmt::format("its answer of {} bytes is longer than it may be", length);
        return std::nullopt;
    }
    if (WIFSIGNALED(status)) {
        why = fmt::format("it stopped on signal {} ({})", WTERMSIG(status),
                          strsignal(WTERMSIG(status)));
        return std::nullopt;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        why =
            fmt::format("it stopped with status {}", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        return std::nullopt;
    }
    if (!complete) {
        why = "its answer was cut short";
        return std::nullopt;
    }
    return bytes;
}

} // namespace crt::scene
