// Temporary output files: created exclusively under a random name, listed for signal handlers.
#include "tracer/image_io/temporary_file.hpp"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace crt::tracer::image_io {
namespace {

namespace fs = std::filesystem;

// A slot of the table is free, being filled or emptied by its owner, listed, or taken by a
// signal handler (which then reads its path: no owner may write it any more).
enum SlotState : int { kFree, kBusy, kListed, kTakenByHandler };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};

// More than the files one program writes at once (crtc writes one, or two while a numbered
// frame is copied); a temporary beyond it still works but is not removed by a signal.
constexpr int kSlots = 16;
Slot slots[kSlots];

int listTemporary(const std::string& path) {
    if (path.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slots[i].state.compare_exchange_strong(expected, kBusy)) continue;
        std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
        slots[i].state.store(kListed, std::memory_order_release);
        return i;
    }
    return -1;
}

void unlistTemporary(int slot) {
    if (slot < 0) return;
    // A handler that took the slot is removing the file and ending the program: leave it be.
    int expected = kListed;
    slots[slot].state.compare_exchange_strong(expected, kFree);
}

std::string errnoText() { return std::strerror(errno); }

// Set by removeAllTemporaries: a file created after it would not be removed.
std::atomic<bool> stopping{false};

// Eight letters and digits from the kernel's random source: 2^41 names, none guessable.
std::string randomLetters() {
    static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    unsigned char bytes[8] = {};
    if (::getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes)) {
        // Practically never; the clock and the address still differ per call.
        const auto fallback = std::uint64_t(::clock()) ^ std::uint64_t(reinterpret_cast<std::uintptr_t>(&bytes));
        std::memcpy(bytes, &fallback, sizeof bytes);
    }
    std::string letters;
    for (unsigned char b : bytes) letters += kAlphabet[b % 36];
    return letters;
}

} // namespace

TemporaryFile::TemporaryFile(const std::string& target, std::string& error) : target_(target) {
    const fs::path targetPath(target);
    const fs::path folder = targetPath.parent_path();
    // Hidden, named after the target so that a stray one is recognisable, random in the middle.
    // Appended piece by piece: `"." + std::string` trips GCC 12's -Wrestrict false positive.
    std::string hidden(1, '.');
    hidden += targetPath.filename().string();
    hidden += '.';
    const std::string prefix = (folder / hidden).string();
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string candidate = prefix + randomLetters() + ".tmp";
        // Listed before it exists, so that no moment passes with a file a signal would leave.
        slot_ = listTemporary(candidate);
        // Not mkstemp: its mode 0600 would make every image private; this is the mode (after
        // the umask) that any new file gets.
        fd_ = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ >= 0) {
            path_ = std::move(candidate);
            if (stopping.load()) discard(); // a handler emptied the table in the meantime
            return;
        }
        const int why = errno;
        unlistTemporary(slot_);
        slot_ = -1;
        if (why != EEXIST) {
            error = "cannot create a temporary file beside it: " + std::string(std::strerror(why));
            return;
        }
    }
    error = "cannot create a temporary file beside it: every name tried exists";
}

TemporaryFile::~TemporaryFile() { discard(); }

void TemporaryFile::discard() {
    if (fd_ < 0) return;
    ::close(fd_);
    fd_ = -1;
    ::unlink(path_.c_str());
    unlistTemporary(slot_);
    slot_ = -1;
}

bool TemporaryFile::commit(std::string& error) {
    if (fd_ < 0) {
        error = "the temporary file was not created";
        return false;
    }
    struct stat status {};
    // A writer that ignored a failed write (a full disk) can leave an empty file and report
    // success; close reports what a network file system finds only when the file is flushed.
    // The file is not synced to disk: every render would wait for the disk, which image writers
    // do not make their users do.
    if (::fstat(fd_, &status) != 0) error = errnoText();
    else if (status.st_size == 0) error = "nothing was written (is the disk full?)";
    else if (::close(fd_) != 0) {
        fd_ = -2; // closed: only the name is left to remove
        error = errnoText();
    } else {
        fd_ = -2;
        if (::rename(path_.c_str(), target_.c_str()) != 0) error = errnoText();
    }
    if (!error.empty()) {
        if (fd_ >= 0) ::close(fd_);
        ::unlink(path_.c_str());
    }
    fd_ = -1;
    unlistTemporary(slot_);
    slot_ = -1;
    return error.empty();
}

int removeAllTemporaries() noexcept {
    stopping.store(true);
    int removed = 0;
    for (Slot& slot : slots) {
        int expected = kListed;
        if (slot.state.compare_exchange_strong(expected, kTakenByHandler)) {
            ::unlink(slot.path);
            ++removed;
        }
    }
    return removed;
}

} // namespace crt::tracer::image_io
