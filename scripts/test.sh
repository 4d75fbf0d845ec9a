#!/usr/bin/env bash
# Sets everything up, builds, and runs every test: the Release build, the whole suite again
# under AddressSanitizer and UndefinedBehaviorSanitizer, then the libFuzzer targets for a
# minute each on their corpora (scripts/fuzz.sh: a clang build of the targets, then the runs,
# two at a time). Not `image`: a minute of it from the seeds still finds a new fault of
# OpenImageIO's readers in about one run of twelve (tests/fuzz/README.md), which would make
# the suite's result a draw; its campaigns run apart, and the suite replays its findings.
#   scripts/test.sh            all three
#   scripts/test.sh --quick    the Release build only
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)

scripts/build.sh -DCRT_WERROR=ON
(cd build && ctest --output-on-failure -j "$jobs")

if [ "${1:-}" != "--quick" ]; then
    # Line tables only (-g1): the sanitizers' reports keep their files and lines, and the
    # build is markedly quicker than with full debug information.
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCRT_SANITIZE=ON \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCRT_WERROR=ON >/dev/null
    cmake --build build-asan
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --output-on-failure -j "$jobs")
    scripts/fuzz.sh 60 frontend lsp obj font
fi
echo "all tests passed"
