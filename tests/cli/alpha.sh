#!/usr/bin/env bash
# crtc --alpha: a fourth channel that is the pixel's coverage by the scene, the background
# transparent; straight alpha in PNG and TIFF, premultiplied in OpenEXR; refused where the
# format has no alpha channel. Pixels are read back with oiiotool.
set -u
crtc=$1
command -v oiiotool >/dev/null || { echo "SKIP: oiiotool not found (openimageio-tools)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

# A flat orange sphere (it only glows) over a blue background, small enough that its edge
# pixels are partly covered.
cat >"$work/sphere.crt" <<'CRT'
Settings {
    width -> 8 height -> 6 supersampling -> 3
    background -> Background { color -> rgb(0.2, 0.4, 0.9) }
}
orange = Material { color -> rgb(0, 0, 0) diffuse -> 0 specular -> 0 emission -> rgb(1, 0.5, 0) }
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 0.25 material -> orange } }
CRT

# Every file's stored values, as "x y v0 v1 ..." lines (the color as stored: not multiplied by
# alpha on reading); 8-bit values are scaled to 0..1.
pixels() { # image
    oiiotool --iconfig oiio:UnassociatedAlpha 1 --dumpdata "$1" | python3 -c '
import re, sys
for line in sys.stdin:
    m = re.match(r" *Pixel \((\d+), (\d+)\): ([^(]*)(?:\((.*)\))?", line)
    if m:
        print(m.group(1), m.group(2), (m.group(4) or m.group(3)).strip())'
}

expect_status 0 "--alpha -o .png" "$crtc" -q --alpha -o "$work/a.png" "$work/sphere.crt"
expect_status 0 "the same without --alpha" "$crtc" -q -o "$work/opaque.png" "$work/sphere.crt"
expect_status 0 "--alpha -o .tif" "$crtc" -q --alpha -o "$work/a.tif" "$work/sphere.crt"
expect_status 0 "--alpha -o .exr" "$crtc" -q --alpha -o "$work/a.exr" "$work/sphere.crt"
oiiotool --info "$work/a.png" >"$work/info" 2>&1
expect_text "$work/info" "8 x +6, 4 channel, uint8 png" "--alpha writes an RGBA PNG"
oiiotool --info "$work/a.exr" >"$work/info" 2>&1
expect_text "$work/info" "4 channel, (half|float) openexr" "--alpha writes an RGBA OpenEXR"
for image in a opaque; do pixels "$work/$image.png" >"$work/$image.txt"; done
pixels "$work/a.tif" >"$work/tif.txt"
pixels "$work/a.exr" >"$work/exr.txt"
cmp -s "$work/tif.txt" "$work/a.txt" || fail "the TIFF's pixels differ from the PNG's"
python3 - "$work/a.txt" "$work/opaque.txt" "$work/exr.txt" <<'PY' || failures=$((failures + 1))
import sys
def load(path):
    return {(int(x), int(y)): [float(v) for v in values]
            for x, y, *values in (line.split() for line in open(path))}
png, opaque, exr = (load(path) for path in sys.argv[1:4])
problems = []
clear = [p for p, v in png.items() if v[3] == 0]
full = [p for p, v in png.items() if v[3] == 1]
partial = [p for p, v in png.items() if 0 < v[3] < 1]
if not (clear and full and partial):
    problems.append(f"expected clear, covered and partly covered pixels: {len(clear)}, {len(full)}, {len(partial)}")
if any(png[p][:3] != [0, 0, 0] for p in clear):
    problems.append("a pixel the scene does not cover has a color")
if any(png[p][:3] != opaque[p] for p in full):
    problems.append("a covered pixel differs from the render without --alpha")
for p in partial:
    r, g, b, a = png[p]
    # Straight alpha: the sphere's own orange, neither darkened by the coverage nor mixed with
    # the blue background, which the render without --alpha shows there.
    if abs(r - 1) > 1 / 255 or abs(g - 0.5) > 1 / 255 or b != 0 or opaque[p][2] == 0:
        problems.append(f"edge pixel {p} is not the sphere's color: {png[p]} (opaque: {opaque[p]})")
    # OpenEXR: premultiplied, the PNG's color times alpha.
    if abs(exr[p][3] - a) > 1 / 255 or any(abs(exr[p][c] - png[p][c] * exr[p][3]) > 1 / 255 for c in range(3)):
        problems.append(f"edge pixel {p} in the EXR is not premultiplied: {exr[p]} (PNG: {png[p]})")
for problem in problems:
    print("FAIL:", problem)
sys.exit(1 if problems else 0)
PY

# Formats without alpha are refused before rendering, and write nothing.
for name in a.jpg a.hdr; do
    expect_status 2 "--alpha -o $name" "$crtc" -q --alpha -o "$work/$name" "$work/sphere.crt"
    expect_text "$work/err" "--alpha: '.*$name' is of a format without an alpha channel" "$name refused"
    [ -e "$work/$name" ] && fail "$name was written"
done
expect_status 2 "--alpha with an animated GIF" "$crtc" -q --alpha --frames 2 -o "$work/a.gif" "$work/sphere.crt"
expect_text "$work/err" "without an alpha channel" "a GIF refused"

# Numbered frames of an animation carry alpha too.
expect_status 0 "numbered frames with --alpha" "$crtc" -q --alpha --frames 2 -o "$work/f_%d.png" "$work/sphere.crt"
oiiotool --info "$work/f_1.png" >"$work/info" 2>&1
expect_text "$work/info" "4 channel" "each numbered frame has alpha"
finish
