#!/usr/bin/env bash
# Runs one libFuzzer target of a -DCRT_FUZZ=ON build tree on its seed corpus and past findings.
#   tests/fuzz/run.sh BUILD_DIR TARGET SECONDS [libFuzzer option]...
# TARGET is a folder of tests/fuzz/corpus/ (frontend, obj, font, lsp, image). The corpus grows in
# WORK/corpus and findings land in WORK/findings, WORK being $CRT_FUZZ_WORK or
# BUILD_DIR/fuzz/TARGET; a later run on the same WORK goes on from that corpus. Exit status:
# 0 when the time ran out without a finding, libFuzzer's otherwise.
set -euo pipefail
if [ $# -lt 3 ]; then
    echo "usage: $0 BUILD_DIR TARGET SECONDS [libFuzzer option]..." >&2
    exit 2
fi
fuzz_dir=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
target=$2
seconds=$3
shift 3
program=$build/tests/fuzz_$target
[ -d "$fuzz_dir/corpus/$target" ] || { echo "$0: no corpus for '$target'" >&2; exit 2; }
[ -x "$program" ] || { echo "$0: $program is not built" >&2; exit 2; }

work=${CRT_FUZZ_WORK:-$build/fuzz/$target}
mkdir -p "$work/corpus" "$work/findings" "$work/cwd"
# The seeds and every past finding start the corpus (-n: keep what earlier runs found).
cp -n "$fuzz_dir/corpus/$target"/* "$work/corpus/"
if [ -d "$fuzz_dir/regressions/$target" ]; then
    cp -n "$fuzz_dir/regressions/$target"/* "$work/corpus/"
fi

# Fonts: the seeds are only headers, so the machine's DejaVu fonts (fonts-dejavu-core) start
# the corpus too, read in place.
extra=()
if [ "$target" = font ] && [ -d /usr/share/fonts/truetype/dejavu ]; then
    extra+=(/usr/share/fonts/truetype/dejavu)
fi

options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024
         -print_final_stats=1 -artifact_prefix="$work/findings/")
[ -f "$fuzz_dir/$target.dict" ] && options+=(-dict="$fuzz_dir/$target.dict")
case $target in
# Scripts up to 1 MB: long enough for deep nesting and long loops.
frontend) options+=(-max_len=1048576) ;;
# A session of several messages with a document in them.
lsp) options+=(-max_len=65536) ;;
# DejaVu Sans is 740 KB.
font) options+=(-max_len=1048576) ;;
# No leak checks while fuzzing: in a process with OpenImageIO's thread pools, LeakSanitizer's
# own tracer sometimes crashes (google/sanitizers#1353; once in 14 one-minute runs), which
# libFuzzer reports as a finding. The replay of the corpus in the ASan suite checks leaks.
image) options+=(-detect_leaks=0) ;;
esac
# Undefined behaviour is a finding, not just a report.
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
[ -f "$fuzz_dir/$target.lsan-supp" ] && export LSAN_OPTIONS=suppressions=$fuzz_dir/$target.lsan-supp
# From an empty folder: the front end's `include` reads paths relative to the current one.
cd "$work/cwd"
exec "$program" "$work/corpus" "${extra[@]}" "${options[@]}" "$@"
