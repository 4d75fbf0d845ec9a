#!/usr/bin/env bash
# crtc's command line: exit statuses, modes and the diagnostic format.
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

expect_status() { # expected-status description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$work/out" 2>"$work/err"
    local got=$?
    if [ "$got" != "$want" ]; then
        echo "FAIL: $what: exit status $got, expected $want"
        sed 's/^/  stdout: /' "$work/out" | head -5
        sed 's/^/  stderr: /' "$work/err" | head -5
        failures=$((failures + 1))
    fi
}
expect_text() { # file pattern description
    if ! grep -qE -- "$2" "$1"; then
        echo "FAIL: $3: no match for '$2' in:"
        head -5 "$1" | sed 's/^/  /'
        failures=$((failures + 1))
    fi
}

cat >"$work/good.crt" <<'CRT'
s = Sphere { center -> vec3(0, 0, 0) radius -> 1 }
Scene { s }
CRT
cat >"$work/bad.crt" <<'CRT'
s = Sphere { center -> vec3(0, 0, 0) radius -> "one" }
Scene { s }
CRT
cat >"$work/warn.crt" <<'CRT'
unused = 3
s = Sphere { center -> vec3(0, 0, 0) radius -> 1 }
Scene { s }
CRT
cat >"$work/loop.crt" <<'CRT'
while (true) { }
CRT
cat >"$work/time.crt" <<'CRT'
print(t, clock)
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }
CRT

expect_status 0 "--help" "$crtc" --help
expect_text "$work/out" "usage: crtc" "--help prints usage"
expect_status 0 "--version" "$crtc" --version
expect_text "$work/out" "^crtc [0-9]+\.[0-9]+" "--version prints a version"
expect_status 2 "no script" "$crtc"
expect_text "$work/err" "no script given" "no script message"
expect_status 2 "unknown option" "$crtc" --frobnicate "$work/good.crt"
expect_text "$work/err" "unknown option '--frobnicate'" "unknown option message"
expect_status 2 "missing file" "$crtc" --check "$work/missing.crt"
expect_text "$work/err" "cannot read" "missing file message"
expect_status 2 "bad number" "$crtc" --max-steps many "$work/good.crt"

expect_status 0 "--check on a good script" "$crtc" --check "$work/good.crt"
[ -s "$work/err" ] && { echo "FAIL: --check printed something on a good script"; failures=$((failures + 1)); }
expect_status 1 "--check on a bad script" "$crtc" --check --color never "$work/bad.crt"
expect_text "$work/err" "bad\.crt:1:48: error: attribute 'radius' of Sphere must be a float, not string" "GCC-style diagnostic"
expect_text "$work/err" "^ +\^~~~~$" "caret underline"
expect_status 0 "a warning alone" "$crtc" --check "$work/warn.crt"
expect_text "$work/err" "warning: variable 'unused' is assigned but never used" "unused variable warning"
expect_status 1 "-Werror" "$crtc" --check -Werror "$work/warn.crt"
expect_status 1 "the step limit" "$crtc" --check --max-steps 1000 "$work/loop.crt"
expect_text "$work/err" "exceeded 1000 steps" "step limit message"

expect_status 0 "--dump-scene" "$crtc" --dump-scene "$work/good.crt"
expect_text "$work/out" '"schema": 1' "scene JSON has a schema version"
expect_text "$work/out" '"type": "Sphere"' "scene JSON has the sphere"
expect_status 0 "--dump-ast" "$crtc" --dump-ast "$work/good.crt"
expect_text "$work/out" "Object Sphere <1:5-1:51>" "AST dump shows the object and its range"
expect_status 0 "--time" "$crtc" --check --time 2.5 "$work/time.crt"
expect_text "$work/out" "^2.5 0.0$" "--time sets t"
expect_status 0 "--frames" "$crtc" --check --frames 3 "$work/time.crt"
expect_text "$work/out" "^2 1.0$" "--frames runs every frame with t and clock"

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all crtc command-line checks passed"
