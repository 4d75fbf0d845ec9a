#!/usr/bin/env bash
# crtc --continue: a render stopped half way (Ctrl-C, or killed as by a crash) is finished from
# its resume log into the same bits as an uninterrupted render; a changed scene is refused.
set -u
crtc=$1
# Under the sanitizers (a second argument of 1) the renders are smaller and the path-traced ones
# take fewer paths: they are what takes long there, and the Release suite renders them in full.
# A render that is interrupted must last well over a second, since what it logs reaches the
# file within a second: the interruption waits for that.
paths=768 width=640 height=480
[ "${2:-0}" = 1 ] && paths=128 width=240 height=180
tiles=$(((width + 15) / 16 * ((height + 15) / 16))) # crtc's tiles are 16 pixels square
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

cat >"$work/scene.crt" <<CRT
Settings {
    width -> $width height -> $height supersampling -> 4
    camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }
    lights -> [AreaLight { corner -> vec3(2, 3, -3) edgeA -> vec3(1, 0, 0) edgeB -> vec3(0, 1, 0.5)
                           color -> rgb(1, 1, 1) }]
}
Scene {
    for i in range(10) { Sphere { center -> vec3(i * 0.5 - 2.2, 0, i * 0.3) radius -> 0.4 + t * 0.01 } }
    Plane { normal -> vec3(0, 1, 0) position -> vec3(0, -0.4, 0) }
}
CRT

# Starts a one-thread render in the background, waits until its log holds some tiles (or the
# file `until` exists), then sends `signal`; leaves the exit status in $status. The render logs
# its tiles from the start, or once it has rendered $LOG_AFTER seconds; it is interrupted once
# its log holds $LOG_BYTES bytes (default 200000).
interrupt_render() { # signal log until crtc-arguments...
    local signal=$1 log=$2 until=$3
    shift 3
    "$crtc" --threads 1 --resume-log-after "${LOG_AFTER:-0}" "$@" >"$work/out" 2>"$work/err" &
    local pid=$!
    for _ in $(seq 600); do
        if [ -n "$until" ]; then [ -e "$until" ] && break
        elif [ "$(stat -c %s "$log" 2>/dev/null || echo 0)" -gt "${LOG_BYTES:-200000}" ]; then break; fi
        kill -0 $pid 2>/dev/null || break
        sleep 0.05
    done
    kill -s "$signal" $pid 2>/dev/null || fail "the render ended before it could be interrupted"
    wait $pid 2>/dev/null
    status=$?
}

expect_status 0 "uninterrupted render" "$crtc" -q -o "$work/whole.png" "$work/scene.crt"

# Ctrl-C half way: status 130, no image, a log; --continue finishes it.
interrupt_render INT "$work/.a.png.crtc-resume" "" -o "$work/a.png" "$work/scene.crt"
[ "$status" = 130 ] || fail "Ctrl-C: exit status $status, expected 130"
expect_text "$work/err" "interrupted; no image written; crtc --continue" "Ctrl-C says how to go on"
[ -e "$work/a.png" ] && fail "Ctrl-C left an image"
[ -s "$work/.a.png.crtc-resume" ] || fail "Ctrl-C left no resume log"
expect_status 0 "--continue after Ctrl-C" "$crtc" --continue -o "$work/a.png" "$work/scene.crt"
expect_text "$work/err" "continuing .*a.png: [0-9]+ of $tiles tiles were rendered before" "--continue says what it reuses"
cmp -s "$work/a.png" "$work/whole.png" || fail "the continued render differs from the uninterrupted one"
[ -e "$work/.a.png.crtc-resume" ] && fail "the log is left after the render finished"

# A path-traced render with an AOV: the floats of the image and of the AOV as uninterrupted.
path=(--integrator path --samples "$paths" --width 128 --height 96 --aov variance)
expect_status 0 "uninterrupted path render" "$crtc" -q "${path[@]}" -o "$work/whole.hdr" "$work/scene.crt"
LOG_BYTES=30000 interrupt_render INT "$work/.p.hdr.crtc-resume" "" "${path[@]}" -o "$work/p.hdr" "$work/scene.crt"
[ "$status" = 130 ] || fail "Ctrl-C of a path render: exit status $status, expected 130"
expect_status 0 "--continue a path render" "$crtc" --continue "${path[@]}" -o "$work/p.hdr" "$work/scene.crt"
expect_text "$work/err" "continuing .*p.hdr: [1-9][0-9]* of 48 tiles were rendered before" "--continue reuses path tiles"
cmp -s "$work/p.hdr" "$work/whole.hdr" || fail "the continued path render differs from the uninterrupted one"
if command -v idiff >/dev/null; then
    idiff -fail 0 -warn 0 "$work/p.variance.exr" "$work/whole.variance.exr" >/dev/null ||
        fail "the continued path render's variance differs"
fi

# Motion blur: the samples' times within the shutter are the same in the continued render;
# another shutter is another render.
sed 's/radius -> 0.4 + t \* 0.01 }/radius -> 0.4 } <translate vec3(t * 0.5, 0, 0)>/' "$work/scene.crt" >"$work/moving.crt"
blur=(--integrator path --samples "$paths" --width 128 --height 96 --shutter 0:1)
expect_status 0 "uninterrupted blurred render" "$crtc" -q "${blur[@]}" -o "$work/whole_blur.hdr" "$work/moving.crt"
LOG_BYTES=30000 interrupt_render INT "$work/.m.hdr.crtc-resume" "" "${blur[@]}" -o "$work/m.hdr" "$work/moving.crt"
[ "$status" = 130 ] || fail "Ctrl-C of a blurred render: exit status $status, expected 130"
expect_status 2 "--continue with another shutter" "$crtc" --continue "${blur[@]}" --shutter 0:0.5 -o "$work/m.hdr" "$work/moving.crt"
expect_status 0 "--continue a blurred render" "$crtc" --continue "${blur[@]}" -o "$work/m.hdr" "$work/moving.crt"
expect_text "$work/err" "continuing .*m.hdr: [1-9][0-9]* of 48 tiles were rendered before" "--continue reuses blurred tiles"
cmp -s "$work/m.hdr" "$work/whole_blur.hdr" || fail "the continued blurred render differs from the uninterrupted one"

# Killed outright, as by a crash: the log written up to a second before is enough.
interrupt_render KILL "$work/.b.png.crtc-resume" "" -o "$work/b.png" "$work/scene.crt"
expect_status 0 "--continue after SIGKILL" "$crtc" -q --continue -o "$work/b.png" "$work/scene.crt"
cmp -s "$work/b.png" "$work/whole.png" || fail "the render continued after SIGKILL differs"

# A changed scene or option is refused; so is --continue with nothing to continue.
interrupt_render INT "$work/.c.png.crtc-resume" "" -o "$work/c.png" "$work/scene.crt"
sed -i 's/radius -> 0.4/radius -> 0.41/' "$work/scene.crt"
expect_status 2 "--continue of a changed scene" "$crtc" --continue -o "$work/c.png" "$work/scene.crt"
expect_text "$work/err" "cannot continue: frame 0 is not the frame the interrupted render began" "changed scene message"
sed -i 's/radius -> 0.41/radius -> 0.4/' "$work/scene.crt"
expect_status 2 "--continue with another size" "$crtc" --continue --width $((width / 2)) -o "$work/c.png" "$work/scene.crt"
expect_status 2 "nothing to continue" "$crtc" --continue -o "$work/none.png" "$work/scene.crt"
expect_text "$work/err" "nothing to continue" "nothing to continue message"

# Numbered frames: Ctrl-C during frame 1 names frame 0 as written; --continue renders the rest.
mkdir "$work/whole_frames" "$work/frames"
expect_status 0 "uninterrupted frames" "$crtc" -q --frames 3 --width $((width / 2)) --height $((height / 2)) -o "$work/whole_frames/f%d.png" "$work/scene.crt"
interrupt_render INT "" "$work/frames/f0.png" --frames 3 --width $((width / 2)) --height $((height / 2)) -o "$work/frames/f%d.png" "$work/scene.crt"
sleep 0.1
expect_text "$work/err" "interrupted; frames 0 to 0 written" "Ctrl-C names the frames written"
expect_status 0 "--continue frames" "$crtc" --continue --frames 3 --width $((width / 2)) --height $((height / 2)) -o "$work/frames/f%d.png" "$work/scene.crt"
for f in f0 f1 f2; do
    cmp -s "$work/frames/$f.png" "$work/whole_frames/$f.png" || fail "continued frame $f differs"
done

# By default a frame's tiles are logged once it has rendered five seconds: a render stopped
# sooner leaves no log, and says that there is nothing to continue.
"$crtc" --threads 1 -o "$work/d.png" "$work/scene.crt" >"$work/out" 2>"$work/err" &
pid=$!
for _ in $(seq 600); do
    grep -q "crtc: 30%" "$work/err" && break
    sleep 0.05
done
kill -INT $pid
wait $pid
status=$?
[ "$status" = 130 ] || fail "Ctrl-C before the log started: exit status $status, expected 130"
grep -q -- "--continue" "$work/err" && fail "Ctrl-C before the log started offers --continue"
expect_text "$work/err" "interrupted; no image written" "Ctrl-C before the log started says so"
[ -e "$work/.d.png.crtc-resume" ] && fail "a render stopped before its log started left a log"

# A log started during the frame: the tiles traced before it are traced again, the rest
# reused, and the image is the same bits.
expect_status 0 "uninterrupted heavier render" "$crtc" -q --supersampling 6 -o "$work/whole6.png" "$work/scene.crt"
LOG_AFTER=0.3 interrupt_render INT "$work/.e.png.crtc-resume" "" --supersampling 6 \
    -o "$work/e.png" "$work/scene.crt"
[ "$status" = 130 ] || fail "Ctrl-C after the log started: exit status $status, expected 130"
expect_text "$work/err" "interrupted; no image written; crtc --continue" "the note offers --continue once the log started"
expect_status 0 "--continue of a log started late" "$crtc" --continue --supersampling 6 -o "$work/e.png" "$work/scene.crt"
expect_text "$work/err" "continuing .*e.png: [0-9]+ of $tiles tiles were rendered before" "--continue reuses the tiles logged"
cmp -s "$work/e.png" "$work/whole6.png" || fail "the render continued from a late log differs"

# A render that ends well before the delay (small, so also under the sanitizers) creates no
# file but its image (seen by strace, which lists every file the process creates).
# LeakSanitizer cannot run under a tracer: off there.
if command -v strace >/dev/null; then
    ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        expect_status 0 "a short render under strace" strace -f -qq -o "$work/trace" \
        -e trace=%file "$crtc" -q --width 120 --height 90 -o "$work/f.png" "$work/scene.crt"
    created=$(grep -E '^[0-9]+ +((open|openat)\(.*O_CREAT|(creat|mkdir|mkdirat|link|linkat|symlink|symlinkat)\()' \
        "$work/trace" | grep -v -- '= -1 E' | grep -oE '"[^"]*"' | head -n 1000 | sort -u | tr '\n' ' ')
    case $created in
    "\"$work/.f.png."*".tmp\" ") ;;
    *) fail "a short render created more than its image's temporary file: $created" ;;
    esac
    [ -e "$work/f.png" ] || fail "the short render wrote no image"
else
    echo "SKIP: strace is not installed (scripts/setup.sh installs it): the files a short render creates are not checked"
fi

expect_status 2 "--continue of a GIF" "$crtc" --continue --frames 3 -o "$work/x.gif" "$work/scene.crt"
expect_text "$work/err" "cannot finish an animated GIF" "GIF message"

finish
