#!/usr/bin/env bash
# Sets everything up, builds, and runs every test: the Release build, the whole suite again
# under AddressSanitizer and UndefinedBehaviorSanitizer, then the libFuzzer targets for a
# minute each on their corpora (scripts/fuzz.sh: a clang build of the targets, then the runs,
# two at a time).
#   scripts/test.sh            all three
#   scripts/test.sh --quick    the Release build only
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)

scripts/build.sh -DCRT_WERROR=ON
(cd build && ctest --output-on-failure -j "$jobs")

if [ "${1:-}" != "--quick" ]; then
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCRT_SANITIZE=ON \
        -DCRT_WERROR=ON >/dev/null
    cmake --build build-asan
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --output-on-failure -j "$jobs")
    scripts/fuzz.sh 60
fi
echo "all tests passed"
