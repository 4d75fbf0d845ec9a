#!/usr/bin/env bash
# crtc's command line: exit statuses, modes and the diagnostic format.
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

source "$(dirname "$0")/expect.sh"

cat >"$work/good.crt" <<'CRT'
s = Sphere { center -> vec3(0, 0, 0) radius -> 1 }
Scene { s }
Settings { ambient -> rgb(0.2, 0.2, 0.2) }
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
expect_text "$work/out" "Usage: crtc" "--help prints usage"
expect_status 0 "--version" "$crtc" --version
expect_text "$work/out" "^crtc [0-9]+\.[0-9]+" "--version prints a version"
expect_status 2 "no script" "$crtc"
expect_text "$work/err" "no script given" "no script message"
expect_status 2 "unknown option" "$crtc" --frobnicate "$work/good.crt"
expect_text "$work/err" "unknown option '--frobnicate'" "unknown option message"
expect_status 2 "missing file" "$crtc" --check "$work/missing.crt"
expect_text "$work/err" "cannot read '.*missing.crt': no such file" "missing file message says why"
expect_status 2 "a folder as the script" "$crtc" --check "$work"
expect_text "$work/err" "cannot read '.*': it is a folder" "a folder is named as one"
expect_status 2 "bad number" "$crtc" --max-steps many "$work/good.crt"
expect_status 2 "--width above --max-size" "$crtc" --width 900 --max-size 800 -o "$work/big.png" "$work/good.crt"
expect_text "$work/err" "--width 900 is above the image size limit 800 \(raise it with --max-size\)" "size limit message"
[ -e "$work/big.png" ] && { echo "FAIL: an image was written past the size limit"; failures=$((failures + 1)); }
expect_status 0 "--width at --max-size" "$crtc" --width 800 --height 30 --max-size 800 -q -o "$work/fits.png" "$work/good.crt"

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
expect_text "$work/out" '"schema": 3' "scene JSON has a schema version"
expect_text "$work/out" '"type": "Sphere"' "scene JSON has the sphere"
expect_status 0 "--dump-ast" "$crtc" --dump-ast "$work/good.crt"
expect_text "$work/out" "Object Sphere <1:5-1:51>" "AST dump shows the object and its range"
expect_status 0 "--time" "$crtc" --check --time 2.5 "$work/time.crt"
expect_text "$work/out" "^2.5 0.0$" "--time sets t"
expect_status 0 "--frames" "$crtc" --check --frames 3 "$work/time.crt"
expect_text "$work/out" "^2 1.0$" "--frames runs every frame with t and clock"

# --- rendering: output names and formats, animation, --stats, -q, sizes, Ctrl-C
expect_file() { # path description
    if [ ! -s "$1" ]; then
        echo "FAIL: $2: $1 was not written"
        failures=$((failures + 1))
    fi
}
expect_no_file() { # path description
    if [ -e "$1" ]; then
        echo "FAIL: $2: $1 exists"
        failures=$((failures + 1))
    fi
}
expect_info() { # image pattern description: oiiotool's header summary of the image matches
    command -v oiiotool >/dev/null || return 0
    oiiotool --info "$1" >"$work/info" 2>&1
    expect_text "$work/info" "$2" "$3"
}
mkdir -p "$work/scenes" "$work/images" "$work/elsewhere"
cat >"$work/scenes/tiny.crt" <<'CRT'
Settings { width -> 32 height -> 24 ambient -> rgb(0.2, 0.2, 0.2) }
Scene { Sphere { center -> vec3(0, 0, 1) radius -> 0.5 } }
CRT
crtc_path=$(cd "$(dirname "$crtc")" && pwd)/$(basename "$crtc")
cd "$work/elsewhere" || exit 1
expect_status 0 "render with the default output name" "$crtc_path" -q "$work/scenes/tiny.crt"
cd - >/dev/null || exit 1
expect_file "$work/scenes/tiny.png" "the default output is the script's name with .png, beside it"
expect_info "$work/scenes/tiny.png" "32 x +24, 3 channel, uint8 png" "default output is a 32x24 RGB PNG"
expect_no_file "$work/elsewhere/tiny.png" "the default output does not go to the working directory"

expect_status 0 "-o x.exr" "$crtc" -q -o "$work/images/x.exr" "$work/scenes/tiny.crt"
expect_info "$work/images/x.exr" "3 channel, (half|float) openexr" "-o .exr writes OpenEXR"
expect_status 0 "-o x.jpg" "$crtc" -q -o "$work/images/x.jpg" "$work/scenes/tiny.crt"
expect_info "$work/images/x.jpg" "3 channel, uint8 jpeg" "-o .jpg writes JPEG"
expect_status 2 "an unknown output extension" "$crtc" -o "$work/images/x.xyz" "$work/scenes/tiny.crt"
expect_text "$work/err" "cannot write '.*x\.xyz': unknown image format" "unknown extension message"
expect_no_file "$work/images/x.xyz" "an unknown extension writes nothing"

expect_status 0 "--frames 3 -o anim.gif" "$crtc" -q --frames 3 -o "$work/images/anim.gif" "$work/scenes/tiny.crt"
expect_info "$work/images/anim.gif" "\(3 subimages\)" "the GIF has 3 subimages"
expect_status 0 "--frames 3 -o f_%02d.png" "$crtc" -q --frames 3 -o "$work/images/f_%02d.png" "$work/scenes/tiny.crt"
for i in 00 01 02; do expect_file "$work/images/f_$i.png" "numbered frame $i"; done
expect_no_file "$work/images/f_03.png" "no fourth numbered frame"

# --format prints the script formatted, refuses a script with syntax errors, and -o
# writes the file.
printf 'x=1+2\nScene {\nSphere{center->vec3(0,0,0) radius->x}\n}\n' >"$work/messy.crt"
expect_status 0 "--format" "$crtc" --format "$work/messy.crt"
expect_text "$work/out" "^x = 1 \+ 2$" "--format spaces operators"
expect_text "$work/out" "^    Sphere \{ center -> vec3\(0, 0, 0\) radius -> x \}$" "--format indents and spaces"
expect_status 0 "--format -o" "$crtc" --format -o "$work/tidy.crt" "$work/messy.crt"
expect_status 0 "--format of formatted text" "$crtc" --format "$work/tidy.crt"
if ! cmp -s "$work/out" "$work/tidy.crt"; then
    echo "FAIL: --format is not idempotent"
    failures=$((failures + 1))
fi
printf 'Scene {\n' >"$work/open.crt"
expect_status 1 "--format of a script with a syntax error" "$crtc" --format "$work/open.crt"
expect_text "$work/err" "not formatted" "--format says why it refused"

# Frames whose scene does not change are not rendered again: tiny.crt never reads t.
expect_status 0 "--frames 3 of a still scene" "$crtc" --stats --frames 3 -o "$work/images/still.gif" "$work/scenes/tiny.crt"
expect_text "$work/err" "frames reused unchanged 2" "unchanged frames are reused"
expect_text "$work/err" "stats: rays: camera 768," "only the first frame is traced"
cat >"$work/scenes/moving.crt" <<'CRT'
Settings { width -> 32 height -> 24 }
Scene { Sphere { center -> vec3(0.1 * t, 0, 1) radius -> 0.5 } }
CRT
expect_status 0 "--frames 3 of a moving scene" "$crtc" --stats --frames 3 -o "$work/images/moving.gif" "$work/scenes/moving.crt"
expect_text "$work/err" "frames reused unchanged 0" "changing frames are all rendered"
# In a numbered sequence an unchanged frame is the previous file again; a changed one is not.
expect_status 0 "--frames 3 -o still_%d.png" "$crtc" --stats --frames 3 -o "$work/images/still_%d.png" "$work/scenes/tiny.crt"
expect_text "$work/err" "frames reused unchanged 2" "unchanged numbered frames are reused"
if ! cmp -s "$work/images/still_0.png" "$work/images/still_2.png"; then
    echo "FAIL: an unchanged numbered frame differs from the first"
    failures=$((failures + 1))
fi
expect_status 0 "--frames 2 -o moving_%d.png" "$crtc" -q --frames 2 -o "$work/images/moving_%d.png" "$work/scenes/moving.crt"
if cmp -s "$work/images/moving_0.png" "$work/images/moving_1.png"; then
    echo "FAIL: two frames of a moving scene are the same file"
    failures=$((failures + 1))
fi
if ls -a "$work/images" | grep -q '\.tmp$'; then
    echo "FAIL: a temporary file was left among the images"
    failures=$((failures + 1))
fi

# A bad OBJ file is an error of the script at `file ->`, with a note at the file's line, for
# a render and for --check.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' >"$work/scenes/broken.obj"
cat >"$work/scenes/mesh.crt" <<'CRT'
Settings { width -> 32 height -> 24 }
Scene { Mesh { file -> "broken.obj" } }
CRT
expect_status 1 "a broken OBJ file" "$crtc" -q -o "$work/images/mesh.png" "$work/scenes/mesh.crt"
expect_text "$work/err" "^$work/scenes/mesh\.crt:2:24: error: bad mesh 'broken\.obj': vertex index 7 out of range" \
    "the OBJ error is at the script's file attribute"
expect_text "$work/err" "broken\.obj:4:7: note: line 4 of the mesh" "the note points at the OBJ's line and column"
expect_text "$work/err" "^ +f 1 2 7$" "the note quotes the OBJ's line"
expect_no_file "$work/images/mesh.png" "no image for a broken mesh"
expect_status 1 "--check of a broken OBJ file" "$crtc" --check "$work/scenes/mesh.crt"
expect_text "$work/err" "mesh\.crt:2:24: error: bad mesh" "--check reports the bad mesh"

expect_status 0 "--stats" "$crtc" --stats -o "$work/images/s.png" "$work/scenes/tiny.crt"
expect_text "$work/err" "stats: rays: camera 768, reflection 0, refraction 0, shadow 0" "--stats counts the rays"
expect_text "$work/err" "stats: BVH nodes visited [0-9]+, intersection tests [0-9]+" "--stats counts BVH work"
expect_text "$work/err" "stats: shading: plain$" "--stats says a grey ball takes none of the shading it can skip"
cat >"$work/scenes/lace.crt" <<'CRT'
Settings { width -> 32 height -> 24 }
lace = Material { texture -> Checker { colors -> [[0, rgba(1, 1, 1, 1)], [1, rgba(1, 1, 1, 0)]] } }
Scene {
    Sphere { center -> vec3(0, 0, 1) radius -> 0.5
        material -> MaterialMap { pattern -> Gradient { } materials -> [[0, lace], [1, Material { }]] } }
}
CRT
expect_status 0 "--stats of a material map" "$crtc" --stats -o "$work/images/lace.png" "$work/scenes/lace.crt"
expect_text "$work/err" "stats: shading: .*textures, material blends, see-through colours$" \
    "--stats names the material blend and the see-through colour"
expect_status 0 "-q" "$crtc" -q -o "$work/images/q.png" "$work/scenes/tiny.crt"
if [ -s "$work/out" ] || [ -s "$work/err" ]; then
    echo "FAIL: -q printed something on success"
    failures=$((failures + 1))
fi
expect_status 0 "--width/--height" "$crtc" -q --width 40 --height 30 -o "$work/images/sized.png" "$work/scenes/tiny.crt"
expect_info "$work/images/sized.png" "40 x +30" "--width 40 --height 30 sizes the image"
expect_status 0 "--png-compression 0" "$crtc" -q --png-compression 0 -o "$work/images/raw.png" "$work/scenes/tiny.crt"
expect_status 0 "--png-compression 9" "$crtc" -q --png-compression 9 -o "$work/images/small.png" "$work/scenes/tiny.crt"
if [ "$(stat -c %s "$work/images/raw.png")" -le "$(stat -c %s "$work/images/small.png")" ]; then
    echo "FAIL: --png-compression 0 did not write a bigger file than --png-compression 9"
    failures=$((failures + 1))
fi
expect_status 2 "an output folder that does not exist" "$crtc" -q -o "$work/images/missing/x.png" "$work/scenes/tiny.crt"
expect_text "$work/err" "cannot write .*missing/x.png.*does not exist" "the streamed output names the missing folder"
expect_no_file "$work/images/missing" "nothing is created for an unwritable output"
expect_status 2 "--png-compression 10" "$crtc" -q --png-compression 10 -o "$work/images/bad.png" "$work/scenes/tiny.crt"
expect_text "$work/err" "--png-compression needs an integer from 0 to 9" "--png-compression range message"

# A render far longer than the wait: Ctrl-C must exit 130 and leave no image (nor a temporary).
cp "$(dirname "$0")/scenes/heavy.crt" "$work/scenes/heavy.crt"
# An output that cannot be written stops the render at the first finished rows, rather than after
# tracing the whole image: the progress lines (standard error is not a terminal) stop short of 100 %.
expect_status 2 "a long render to a folder that does not exist" \
    "$crtc" -o "$work/images/missing/heavy.png" "$work/scenes/heavy.crt"
expect_text "$work/err" "cannot write .*missing/heavy.png.*does not exist" "the failed output is named"
if grep -q "100%" "$work/err"; then
    echo "FAIL: a render whose output failed went on to the end"
    failures=$((failures + 1))
fi
expect_no_file "$work/images/missing" "nothing is created for the failed output"

# The handler is installed once the script is evaluated; a signal before that kills crtc with the
# same status 130 but proves less, so wait longer until crtc reports the interruption itself.
for delay in 0.5 1.5 4; do
    "$crtc" -q -o "$work/images/heavy.png" "$work/scenes/heavy.crt" >"$work/out.heavy" 2>"$work/err.heavy" &
    pid=$!
    sleep "$delay"
    kill -INT "$pid"
    wait "$pid"
    status=$?
    grep -q "interrupted; no image written" "$work/err.heavy" && break
done
if [ "$status" != 130 ]; then
    echo "FAIL: SIGINT during a render: exit status $status, expected 130"
    failures=$((failures + 1))
fi
expect_text "$work/err.heavy" "crtc: interrupted; no image written" "SIGINT message"
expect_no_file "$work/images/heavy.png" "an interrupted render leaves no output"
# Only the resume log remains, for --continue (tests/cli/resume.sh).
leftovers=$(find "$work/images" -name '*heavy*' ! -name '.heavy.png.crtc-resume' | head -3)
if [ -n "$leftovers" ]; then
    echo "FAIL: an interrupted render left files: $leftovers"
    failures=$((failures + 1))
fi

# PNG, the default output, and OpenEXR are written without the image module (OpenImageIO): a
# render to either succeeds with the module missing, and is a valid image of the right size
# (an EXR with alpha too), whose floats are those the module writes to a Radiance HDR file
# (to the HDR's 8-bit mantissas). A format that needs the module fails with its name instead.
CRT_IMAGE_IO_MODULE=$work/no_such_module.so expect_status 0 "a PNG render without the image module" \
    "$crtc" -q --width 40 --height 30 -o "$work/images/no_module.png" "$work/scenes/tiny.crt"
expect_info "$work/images/no_module.png" "40 x +30, 3 channel, uint8 png" "the PNG written without the module"
CRT_IMAGE_IO_MODULE=$work/no_such_module.so expect_status 0 "an EXR render without the image module" \
    "$crtc" -q --alpha --width 40 --height 30 -o "$work/images/no_module.exr" "$work/scenes/tiny.crt"
expect_info "$work/images/no_module.exr" "40 x +30, 4 channel, float openexr" "the EXR written without the module"
if command -v oiiotool >/dev/null; then
    "$crtc" -q --width 40 --height 30 -o "$work/images/module.hdr" "$work/scenes/tiny.crt"
    "$crtc" -q --width 40 --height 30 -o "$work/images/builtin.exr" "$work/scenes/tiny.crt"
    idiff -fail 0.01 -warn 0.01 "$work/images/module.hdr" "$work/images/builtin.exr" >/dev/null ||
        fail "the EXR written without the module holds other pixels than the module's HDR of the same render"
    oiiotool --stats "$work/images/builtin.exr" | grep -qE "Stats Max: +(0\.[0-9]*[1-9]|[1-9])" ||
        fail "the EXR of the tiny scene is black: $(oiiotool --stats "$work/images/builtin.exr" | grep Max)"
fi
CRT_IMAGE_IO_MODULE=$work/no_such_module.so expect_status 2 "a TIFF render without the image module" \
    "$crtc" -q -o "$work/images/none.tif" "$work/scenes/tiny.crt"
expect_text "$work/err" "no_such_module" "the missing module is named"
expect_no_file "$work/images/none.tif" "no TIFF is written without the module"

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all crtc command-line checks passed"
