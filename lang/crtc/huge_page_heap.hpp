// Backs crtc's heap with transparent huge pages, so building a large scene faults in 2 MB
// pages instead of 4 KB ones.
#pragma once

namespace crt::driver {

/// Sets up the C library's allocator so that every allocation of the process comes from
/// one heap advised to use transparent huge pages. Call first thing in main, before any
/// thread starts. Returns whether the heap was advised; false in sanitizer builds (their
/// allocator is not the C library's) and on kernels without transparent huge pages, where
/// allocation works as before.
bool useHugePageHeap();

/// Whether useHugePageHeap set the heap up (the Prefaulter works only then).
bool hugePageHeapInUse();

} // namespace crt::driver
