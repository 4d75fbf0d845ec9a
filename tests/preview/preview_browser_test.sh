#!/usr/bin/env bash
# The live preview in a real browser: Debian's chromium driven headless by puppeteer-core
# (installed here, pinned, into the build tree; it downloads no browser).
#   preview_browser_test.sh CRTC OUTPUT_DIR
# Screenshots go to OUTPUT_DIR. Exits 77 (skipped) when chromium, node or npm is absent.
set -euo pipefail
crtc=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
puppeteer_version=23.9.0

for tool in chromium node npm; do
    if ! command -v "$tool" >/dev/null; then
        echo "skipped: $tool is not installed (scripts/setup.sh installs it)" >&2
        exit 77
    fi
done

modules=$out/../node_modules
if [ ! -f "$modules/puppeteer-core/package.json" ] ||
   ! grep -q "\"version\": \"$puppeteer_version\"" "$modules/puppeteer-core/package.json"; then
    mkdir -p "$out/.."
    PUPPETEER_SKIP_DOWNLOAD=1 npm install --silent --no-audit --no-fund --no-save \
        --prefix "$out/.." "puppeteer-core@$puppeteer_version" >&2
fi

rm -rf "$out"
mkdir -p "$out"
cp "$here/scene.crt" "$out/scene.crt"

"$crtc" --preview --frames 3 --threads 2 "$out/scene.crt" >"$out/stdout.txt" 2>"$out/stderr.txt" &
crtc_pid=$!
trap 'kill "$crtc_pid" 2>/dev/null || true' EXIT
for _ in $(seq 100); do
    [ -s "$out/stdout.txt" ] && break
    sleep 0.1
done
url=$(head -n 1 "$out/stdout.txt" | sed -n 's/^preview: //p')
if [ -z "$url" ]; then
    echo "crtc printed no preview URL" >&2
    cat "$out/stderr.txt" >&2
    exit 1
fi

PUPPETEER_DIR=$(cd "$out/.." && pwd) node "$here/preview_browser_test.mjs" "$url" "$out/scene.crt" "$out"

# The page's "stop" button ended crtc, and cleanly.
status=0
for _ in $(seq 100); do
    kill -0 "$crtc_pid" 2>/dev/null || break
    sleep 0.1
done
if kill -0 "$crtc_pid" 2>/dev/null; then
    echo "crtc still runs after the page asked it to stop" >&2
    exit 1
fi
wait "$crtc_pid" || status=$?
trap - EXIT
if [ "$status" -ne 0 ]; then
    echo "crtc --preview exited with status $status" >&2
    cat "$out/stderr.txt" >&2
    exit 1
fi
if ls "$out"/*.tmp >/dev/null 2>&1; then
    echo "crtc left a temporary file behind" >&2
    exit 1
fi
# SIGTERM (as Ctrl-C) stops it too, with status 0.
"$crtc" --preview --threads 2 "$out/scene.crt" >"$out/stdout2.txt" 2>"$out/stderr2.txt" &
crtc_pid=$!
for _ in $(seq 100); do
    [ -s "$out/stdout2.txt" ] && break
    sleep 0.1
done
kill -TERM "$crtc_pid"
status=0
wait "$crtc_pid" || status=$?
if [ "$status" -ne 0 ]; then
    echo "crtc --preview exited with status $status after SIGTERM" >&2
    exit 1
fi
echo "preview browser test passed; screenshots in $out"
