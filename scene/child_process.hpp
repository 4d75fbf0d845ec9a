// Runs a piece of work in a child process and takes back the bytes it produces: for code that
// reads untrusted files and that the project cannot fix (a third-party parser). Whatever that
// code does wrong (a crash, a write through a stale pointer, an abort on a failed assertion)
// happens in the child, and the caller gets an error instead.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace crt::scene {

/// Calls `work` in a forked child and returns the bytes it returned; nullopt, with `why` ("it
/// stopped on signal 11 (Segmentation fault)"), when the child did not finish, or returned
/// more than `maxBytes`. The child leaves by _exit: no destructors, no exit handlers of the
/// parent run in it.
std::optional<std::string> inChildProcess(const std::function<std::string()>& work,
                                          uint64_t maxBytes, std::string& why);

} // namespace crt::scene
