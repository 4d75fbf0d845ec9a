// Runs work on a thread with a large stack: the resolver and the interpreter recurse over
// the AST, and scripts may nest expressions or macro calls hundreds of thousands deep. The
// nesting those walks allow follows from the stack they actually got.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

namespace crt::lang {

#if defined(__SANITIZE_ADDRESS__)
/// AddressSanitizer's red zones make every frame several times larger: the same nesting
/// needs a larger stack (address space; only the pages touched are committed).
inline constexpr size_t kStackScale = 4;
#else
inline constexpr size_t kStackScale = 1;
#endif
/// Stack reserved for front-end work. Only the pages touched are ever committed.
inline constexpr size_t kFrontEndStackBytes = kStackScale << 30;
/// The deepest nesting of expressions and blocks (and, while evaluating, of expressions
/// across macro calls) any front-end walk accepts, with the full stack.
inline constexpr uint32_t kMaxNesting = 1'000'000;
/// Stack one nesting level may take in the deepest recursive walk, with room to spare.
inline constexpr size_t kStackBytesPerNestingLevel = kStackScale * 1024;

/// Calls `work` on a new thread with a `kFrontEndStackBytes` stack and waits for it. If such a
/// thread cannot be made (an address-space limit), calls it directly on the current stack,
/// with a nesting limit that fits that stack, and warns once on standard error.
void runOnLargeStack(const std::function<void()>& work);

/// The nesting limit for front-end work on this thread: kMaxNesting inside runOnLargeStack
/// with the large stack, less when it ran on a smaller one.
uint32_t maxNesting();

} // namespace crt::lang
