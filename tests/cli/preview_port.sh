#!/usr/bin/env bash
# crtc --preview --port: a port another preview listens on is refused, naming it, and the first
# preview keeps every request (no second listener shares the port); --port 0 is a free port.
set -u
crtc=$1
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; wait 2>/dev/null; rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

cat >"$work/scene.crt" <<'CRT'
Settings { width -> 32 height -> 24 }
Scene { Sphere { center -> vec3(0, 0, 3) radius -> 1 } }
CRT

# Starts a preview in the background; its URL (or nothing) in $url.
start_preview() { # name crtc-arguments...
    local name=$1
    shift
    "$crtc" --preview "$@" "$work/scene.crt" >"$work/$name.out" 2>"$work/$name.err" &
    for _ in $(seq 100); do
        [ -s "$work/$name.out" ] && break
        sleep 0.1
    done
    url=$(sed -n 's/^preview: //p' "$work/$name.out" | head -n 1)
}

start_preview first --port 0
[ -n "$url" ] || fail "a preview on --port 0 printed no URL: $(cat "$work/first.err")"
port=$(printf '%s\n' "$url" | sed -n 's|^http://127.0.0.1:\([0-9]*\)/.*|\1|p')
[ -n "$port" ] && [ "$port" -gt 0 ] || fail "no port in the URL '$url'"

# (Under a time limit: a second preview that listened would run until stopped.)
expect_status 2 "a second preview on the same port" timeout 20 "$crtc" --preview --port "$port" "$work/scene.crt"
expect_text "$work/err" "cannot listen on 127.0.0.1:$port: the port is taken" "the taken port is named"

# The first preview answers every request with its token: no other process took any.
codes=$(python3 - "$url" <<'PY'
import sys, urllib.error, urllib.request
for _ in range(10):
    try:
        print(urllib.request.urlopen(sys.argv[1], timeout=10).status)
    except urllib.error.HTTPError as e:
        print(e.code)
PY
)
[ "$(printf '%s\n' "$codes" | sort -u)" = 200 ] ||
    fail "the first preview's answers to ten requests: $(printf '%s' "$codes" | tr '\n' ' ')"

expect_status 2 "a port out of range" timeout 20 "$crtc" --preview --port 65536 "$work/scene.crt"
finish
