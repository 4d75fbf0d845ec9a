// Runs work on a thread with a large stack: the resolver and the interpreter recurse over
// the AST, and scripts may nest expressions or macro calls tens of thousands deep.
#pragma once

#include <cstddef>
#include <functional>

namespace crt::lang {

/// Stack reserved for front-end work. Only the pages touched are ever committed.
inline constexpr size_t kFrontEndStackBytes = size_t{1} << 30;

/// Calls `work` on a new thread with a `kFrontEndStackBytes` stack and waits for it.
/// Falls back to calling it directly if such a thread cannot be made.
void runOnLargeStack(const std::function<void()>& work);

} // namespace crt::lang
