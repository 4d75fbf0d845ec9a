#!/usr/bin/env bash
# Builds the libFuzzer targets with clang in build-fuzz/ and runs each for SECONDS on a copy
# of its corpus, two at a time (tests/fuzz/README.md). Any finding fails the run, and the
# finding's input is left in build-fuzz/fuzz/<target>/findings/.
#   scripts/fuzz.sh [SECONDS [TARGET...]]    default 60 seconds, every target
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
scripts/setup.sh --fuzz

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
    for corpus in tests/fuzz/corpus/*/; do targets+=("$(basename "$corpus")"); done
fi
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCRT_FUZZ=ON >/dev/null
# Only the fuzz targets and the libraries they link, not the whole project.
cmake --build build-fuzz --target "${targets[@]/#/fuzz_}"

# Two targets at a time, each on one core; a target's log is shown when it fails.
rm -rf build-fuzz/fuzz
mkdir -p build-fuzz/fuzz
printf '%s\n' "${targets[@]}" | xargs -P 2 -I{} sh -c '
    if tests/fuzz/run.sh build-fuzz "$1" "$2" >"build-fuzz/fuzz/$1.log" 2>&1; then
        echo "fuzz_$1: $(grep -a "stat::number_of_executed_units" "build-fuzz/fuzz/$1.log" | tr -dc 0-9) inputs, no finding"
    else
        cat "build-fuzz/fuzz/$1.log" >&2
        # The input itself, for a run on a machine whose files are gone afterwards (CI).
        for finding in build-fuzz/fuzz/$1/findings/*; do
            [ -f "$finding" ] && [ "$(stat -c %s "$finding")" -le 65536 ] || continue
            echo "fuzz_$1: $(basename "$finding") in base64: $(base64 -w0 "$finding")" >&2
        done
        echo "fuzz_$1: FAILED (the input is in build-fuzz/fuzz/$1/findings/)" >&2
        exit 1
    fi' sh {} "$seconds"
