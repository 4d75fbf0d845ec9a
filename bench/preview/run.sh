#!/usr/bin/env bash
# crtc --preview's latency: from a save to the first coarse image and to the full image,
# and frames per second while orbiting with the mouse, on every demo at 800x600, 2 threads.
#   bench/preview/run.sh [CRTC [DEMO...]]   (default build/bin/crtc and every demo;
#                                          CRTC=... also works)
# Needs node (for fetch and streams); prints a Markdown table.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
crtc=${1:-${CRTC:-$root/build/bin/crtc}}
shift || true
demos=("$@")
[[ ${#demos[@]} -gt 0 ]] || demos=("$root"/demos/*.crt)
[[ -x $crtc ]] || { echo "$0: no crtc at '$crtc' (build it or pass its path)" >&2; exit 2; }
command -v node >/dev/null || { echo "$0: node is needed" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "| demo | save → first image (ms) | save → full image (ms) | orbit, draft (frames/s) |"
echo "| --- | ---: | ---: | ---: |"
for demo in "${demos[@]}"; do
    name=$(basename "$demo" .crt)
    demo=$root/demos/$name.crt
    # A copy beside the original, so that its includes and "/..." assets resolve alike.
    script="$root/demos/.bench-preview-$name.crt"
    cp "$demo" "$script"
    "$crtc" --preview --width 800 --height 600 --threads 2 "$script" >"$out/$name.url" 2>"$out/$name.err" &
    pid=$!
    for _ in $(seq 100); do [[ -s $out/$name.url ]] && break; sleep 0.1; done
    url=$(sed -n 's/^preview: //p' "$out/$name.url")
    node "$root/bench/preview/measure.mjs" "$url" "$script" "$name" || echo "| $name | failed | | |"
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    rm -f "$script"
done
