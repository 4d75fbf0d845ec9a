#!/usr/bin/env bash
# crtc --preview's server as a program meets it: a port another preview listens on is refused,
# naming it, and the first preview keeps every request (no second listener shares the port);
# --port 0 is a free port; every error of the HTTP API is {"error": "why"} (docs/preview.md).
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

# Errors, from the API's handlers and from the HTTP library alike, are JSON with a reason.
python3 - "$url" >"$work/api" <<'PY'
import json, sys, urllib.error, urllib.parse, urllib.request
url = urllib.parse.urlsplit(sys.argv[1])
base = f"{url.scheme}://{url.netloc}"
token = "?" + url.query
def ask(method, path, query, body=None):
    request = urllib.request.Request(base + path + query, data=body, method=method)
    try:
        with urllib.request.urlopen(request, timeout=10) as answer:
            return answer.status, answer.headers.get_content_type(), answer.read()
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get_content_type(), e.read()
for name, method, path, query, body in [
    ("no token", "GET", "/api/state", "", None),
    ("no such path", "GET", "/api/nothing", token, None),
    ("no such method", "DELETE", "/api/state", token, None),
    ("a POST without a body", "POST", "/api/frame", token, None),
    ("a body that is not JSON", "POST", "/api/frame", token, b"frame"),
    ("a side view of no such view", "GET", "/api/viewport.png", token + "&view=below", None),
    ("a side view too large", "GET", "/api/viewport.png", token + "&view=top&pixels=5000", None),
    ("a side view of no width", "GET", "/api/viewport.png", token + "&view=top&width=0", None),
    ("a side view at no number", "GET", "/api/viewport.png", token + "&view=top&across=nan", None),
]:
    status, kind, text = ask(method, path, query, body)
    try:
        why = json.loads(text)["error"]
    except (ValueError, KeyError, TypeError):
        why = None
    ok = status >= 400 and kind == "application/json" and isinstance(why, str) and why
    print(f"{'ok' if ok else 'FAIL'} {name}: {status} {kind} {text[:100]!r}")
PY
grep -v '^ok ' "$work/api" | sed 's/^/  /' | grep . && fail "API errors that are not {\"error\": \"why\"}"
[ "$(grep -c '^ok ' "$work/api")" = 9 ] || fail "the API error checks did not all run: $(cat "$work/api")"

expect_status 2 "a port out of range" timeout 20 "$crtc" --preview --port 65536 "$work/scene.crt"
finish
