#!/usr/bin/env bash
# Animations split into parts: --frame-range renders frames as the whole run does (the same t,
# clock, file numbers and bits), --first-frame and --clock set the numbering and the clock, and
# --time with --frames renders one frame of the animation; motion blur's shutter (--shutter and
# the script's shutteropen and shutterclose).
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

cat >"$work/anim.crt" <<'CRT'
print(t, clock)
Settings { width -> 24 height -> 16 }
Scene { Sphere { center -> vec3(clock * 2.0 - 1.0, 0, 0) radius -> 0.5 } }
CRT

# The whole animation, then the same in two parts: the files are the same bytes.
mkdir "$work/whole" "$work/parts"
expect_status 0 "whole animation" "$crtc" -q --frames 6 -o "$work/whole/f_%02d.png" "$work/anim.crt"
expect_status 0 "frames 0 to 2" "$crtc" -q --frames 6 --frame-range 0:2 -o "$work/parts/f_%02d.png" "$work/anim.crt"
expect_status 0 "frames 3 to 5" "$crtc" -q --frames 6 --frame-range 3:5 -o "$work/parts/f_%02d.png" "$work/anim.crt"
[ "$(ls "$work/parts" | tr '\n' ' ')" = "f_00.png f_01.png f_02.png f_03.png f_04.png f_05.png " ] ||
    fail "the parts wrote $(ls "$work/parts" | tr '\n' ' ')"
for f in "$work"/whole/*.png; do
    cmp -s "$f" "$work/parts/$(basename "$f")" || fail "$(basename "$f") of the parts differs from the whole run's"
done
expect_status 0 "a range prints its frames' t and clock" "$crtc" --check --frames 5 --frame-range 3:4 "$work/anim.crt"
[ "$(tr '\n' ' ' <"$work/out")" = "3 0.75 4 1.0 " ] || fail "frames 3:4 of 5 printed: $(cat "$work/out")"

# Numbering and clock of POV-Ray's +KFI/+KFF and +KI/+KF.
expect_status 0 "--first-frame and --clock" "$crtc" --check --frames 3 --first-frame 10 --clock 0.5:1.5 "$work/anim.crt"
[ "$(tr '\n' ' ' <"$work/out")" = "10 0.5 11 1.0 12 1.5 " ] || fail "--first-frame 10 --clock 0.5:1.5 printed: $(cat "$work/out")"
mkdir "$work/numbered"
expect_status 0 "numbered from --first-frame" "$crtc" -q --frames 2 --first-frame 7 -o "$work/numbered/g%03d.png" "$work/anim.crt"
[ -s "$work/numbered/g007.png" ] && [ -s "$work/numbered/g008.png" ] || fail "--first-frame 7 wrote $(ls "$work/numbered")"

# --time T with --frames N: the one frame T, as a still image, equal to the animation's frame.
expect_status 0 "--time with --frames" "$crtc" -q --frames 6 --time 4 -o "$work/four.png" "$work/anim.crt"
cmp -s "$work/four.png" "$work/whole/f_04.png" || fail "--frames 6 --time 4 differs from frame 4 of the animation"
expect_status 2 "--time not a frame number" "$crtc" --frames 6 --time 2.5 "$work/anim.crt"
expect_text "$work/err" "with --frames, --time needs a frame number, not 2.5" "fractional --time message"

# Ranges outside the animation, and options that need --frames.
expect_status 2 "range beyond the last frame" "$crtc" --frames 6 --frame-range 4:6 "$work/anim.crt"
expect_text "$work/err" "frames 4 to 6 are not within the animation's frames 0 to 5" "range message"
expect_status 2 "reversed range" "$crtc" --frames 6 --frame-range 3:1 "$work/anim.crt"
expect_status 2 "range without --frames" "$crtc" --frame-range 0:1 "$work/anim.crt"
expect_text "$work/err" "--frame-range and --first-frame need --frames" "range without --frames message"
expect_status 2 "a GIF needs .gif" "$crtc" --frames 6 --frame-range 0:1 -o "$work/x.png" "$work/anim.crt"

# A GIF of part of the animation holds just those frames.
expect_status 0 "GIF of a range" "$crtc" --frames 6 --frame-range 2:4 -o "$work/part.gif" "$work/anim.crt"
expect_text "$work/err" "3 frames" "the summary counts the frames rendered"

# Motion blur: a scene that does not move is the same bits with the shutter open; one that
# moves is blurred, the same bits on any number of threads.
cat >"$work/still.crt" <<'CRT'
Settings { width -> 32 height -> 24 supersampling -> 2 }
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 0.5 } <translate vec3(0.5, 0, 0)> }
CRT
cat >"$work/moving.crt" <<'CRT'
Settings { width -> 32 height -> 24 supersampling -> 2 shutterclose -> 0.5 }
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 0.5 } <translate vec3(t, 0, 0)> }
CRT
expect_status 0 "a still scene" "$crtc" -q -o "$work/closed.png" "$work/still.crt"
expect_status 0 "a still scene, the shutter open" "$crtc" -q --shutter 0:1 -o "$work/open.png" "$work/still.crt"
cmp -s "$work/closed.png" "$work/open.png" || fail "a scene that does not move changed with the shutter open"
expect_status 0 "a moving scene, 1 thread" "$crtc" -q --threads 1 -o "$work/blur1.png" "$work/moving.crt"
expect_status 0 "a moving scene, 2 threads" "$crtc" -q --threads 2 -o "$work/blur2.png" "$work/moving.crt"
cmp -s "$work/blur1.png" "$work/blur2.png" || fail "a blurred render differs between 1 and 2 threads"
expect_status 0 "the shutter closed by --shutter" "$crtc" -q --shutter 0:0 -o "$work/sharp.png" "$work/moving.crt"
cmp -s "$work/blur1.png" "$work/sharp.png" && fail "the moving sphere is not blurred"
expect_status 0 "the shutter closed at t = 0" "$crtc" -q --shutter 0:0 -o "$work/sharp0.png" "$work/still.crt"
cmp -s "$work/closed.png" "$work/sharp0.png" || fail "--shutter 0:0 changed a still scene"
expect_status 2 "--shutter closing before it opens" "$crtc" --shutter 1:0.5 "$work/moving.crt"
expect_text "$work/err" "--shutter needs two numbers A:B, A at most B, not '1:0.5'" "--shutter message"
cat >"$work/growing.crt" <<'CRT'
Settings { shutterclose -> 1 }
Scene {
  Sphere { center -> vec3(0, 0, 0) radius -> 0.5 + t } }
CRT
expect_status 1 "a shape that changes across the shutter" "$crtc" --check "$work/growing.crt"
expect_text "$work/err" "growing.crt:3:3: error: this Sphere changes across the shutter \\(between t = 0 and t = 1\\)" \
    "the changing shape is named"

finish
