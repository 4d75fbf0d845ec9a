#!/usr/bin/env bash
# crtc's output files: temporaries that cannot be planted, and none left by a signal.
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
ulimit -c 0 # SIGQUIT below would otherwise dump core
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

cat >"$work/tiny.crt" <<'CRT'
Settings { width -> 24 height -> 16 }
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }
CRT
# Long enough that a signal arrives while the image is being written.
heavy=$(dirname "$0")/scenes/heavy.crt
# Frame 0 is quick, frame 1 long: a signal during frame 1 finds frame 0 written.
cat >"$work/frames.crt" <<'CRT'
Settings {
    width -> 24 + t * 1976 height -> 16 + t * 1484 supersampling -> 1 + t * 3 recursiondepth -> 8
    lights -> [PointLight { origin -> vec3(2, 4, -3) color -> rgb(1, 1, 1) }]
}
m = Material { color -> rgb(0.8, 0.8, 0.8) reflectivity -> 0.8 }
Scene {
    for i in range(40) { Sphere { center -> vec3(i % 8 - 3.5, i / 8 - 2.0, 3.0 + i % 3) radius -> 0.45 material -> m } }
}
CRT

# --- A symbolic link planted where the temporary file used to be named (".out.png.<pid>.<n>.tmp",
# guessable from the process id) is not followed: the file it points to stays as it was. The shell
# plants the links for its own process id, which crtc keeps through exec.
mkdir "$work/planted"
echo "precious" >"$work/victim"
bash -c 'for n in 0 1 2 3; do ln -s "$1" "$2/.out.png.$$.$n.tmp"; done; exec "$3" -q -o "$2/out.png" "$4"' \
    _ "$work/victim" "$work/planted" "$crtc" "$work/tiny.crt" || fail "crtc beside planted links"
[ "$(cat "$work/victim")" = precious ] || fail "a planted temporary link was followed: the victim changed"
[ -f "$work/planted/out.png" ] && [ ! -L "$work/planted/out.png" ] || fail "no image beside planted links"
[ "$(find "$work/planted" -name '.out.png.*' -type l | wc -l)" = 4 ] || fail "the planted links were touched"
# A link at the output's own name is replaced, never written through.
ln -s "$work/victim" "$work/planted/link.png"
"$crtc" -q -o "$work/planted/link.png" "$work/tiny.crt" || fail "crtc over a link"
[ "$(cat "$work/victim")" = precious ] || fail "an output that is a link wrote through it"
[ -f "$work/planted/link.png" ] && [ ! -L "$work/planted/link.png" ] || fail "the output link was not replaced"
# The formatter's output goes through the same temporaries.
bash -c 'ln -s "$1" "$2/f.crt.crtc-format.tmp"; exec "$3" --format -o "$2/f.crt" "$4"' \
    _ "$work/victim" "$work/planted" "$crtc" "$work/tiny.crt" || fail "crtc --format beside a planted link"
[ "$(cat "$work/victim")" = precious ] || fail "crtc --format followed a planted link"
grep -q "Sphere" "$work/planted/f.crt" || fail "crtc --format wrote nothing"

# --- A signal that stops a render removes the temporary file and leaves no image. Each run waits
# until the temporary exists, so the signal surely comes mid-write.
wait_for_temporary() { # folder pid
    for _ in $(seq 600); do
        [ -n "$(find "$1" -name '.*.tmp' 2>/dev/null | head -1)" ] && return 0
        kill -0 "$2" 2>/dev/null || return 1
        sleep 0.05
    done
    return 1
}
for signal in TERM HUP QUIT INT; do
    dir=$work/signal-$signal
    mkdir "$dir"
    "$crtc" -q -o "$dir/heavy.png" "$heavy" 2>"$dir.err" &
    pid=$!
    wait_for_temporary "$dir" "$pid" || fail "SIG$signal: no temporary appeared"
    kill -"$signal" "$pid"
    wait "$pid"
    status=$?
    expected=$((128 + $(kill -l "$signal")))
    [ "$status" = "$expected" ] || fail "SIG$signal: exit status $status, expected $expected"
    grep -q "crtc: interrupted; no image written" "$dir.err" || fail "SIG$signal: no message ($(cat "$dir.err"))"
    # Only the resume log remains, for --continue (tests/cli/resume.sh).
    leftovers=$(find "$dir" -mindepth 1 ! -name '.heavy.png.crtc-resume' | head -3)
    [ -z "$leftovers" ] || fail "SIG$signal left files: $leftovers"
done

# A numbered sequence stopped in frame 1 says that frame 0 was written, and keeps it.
dir=$work/numbered
mkdir "$dir"
"$crtc" -q --frames 2 -o "$dir/f%02d.png" "$work/frames.crt" 2>"$dir.err" &
pid=$!
for _ in $(seq 600); do [ -f "$dir/f00.png" ] && break; sleep 0.05; done
wait_for_temporary "$dir" "$pid" || fail "numbered: no temporary for frame 1 appeared"
kill -TERM "$pid"
wait "$pid"
[ $? = 143 ] || fail "numbered: SIGTERM did not end crtc with 143"
grep -q "frames 0 to 0 written (.*f00.png to .*f00.png)" "$dir.err" ||
    fail "numbered: the written frames are not named: $(cat "$dir.err")"
[ "$(find "$dir" -mindepth 1 ! -name '.f%02d.png.crtc-resume' | sed 's|.*/||')" = f00.png ] ||
    fail "numbered: left $(ls -A "$dir")"

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all output-file checks passed"
