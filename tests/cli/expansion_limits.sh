#!/usr/bin/env bash
# What a small script or file can make the renderer hold ends in an error before it is held:
# entities built (drawn or not), primitives stored after CSG and group expansion and instancing
# (counted before the expansion, by --check too), and images whose header claims more pixels (or
# values) than allowed.
set -u
crtc=$1
sanitized=${2:-0} # 1 for an AddressSanitizer build: its shadow memory needs all the address space
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

# Under an address-space limit where the machine has prlimit, so that a regression fails
# with out of memory instead of taking the machine's memory.
limited=()
if [ "$sanitized" = 1 ]; then
    echo "note: a sanitizer build; the runs are not under an address-space limit"
elif command -v prlimit >/dev/null; then
    limited=(prlimit --as=3000000000)
else
    echo "note: prlimit not found; the runs are not under an address-space limit"
fi
camera='Settings { width -> 8 height -> 8 }'

# CSG doubling: 26 entities, 2^25 primitives. The shared half is stored once, but instances are
# one level deep: it is 2^24 copies. The drawing that passes the limit is the error.
printf '%s\ng = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nfor i in range(25) { g = g + g }\nScene { g }\n' \
    "$camera" >"$work/csg.crt"
for command in --check --dump-scene ""; do
    expect_status 1 "CSG doubled 25 times (${command:-render})" "${limited[@]}" "$crtc" $command -o "$work/csg.png" "$work/csg.crt"
    expect_text "$work/err" "^$work/csg.crt:4:9: error: the scene stores more than 5000000 primitives \(copies count each time; an entity of 16 or more drawn again is stored once\); raise the limit with --max-primitives$" \
        "CSG doubled (${command:-render}): the primitive error at the drawing"
done
[ -e "$work/csg.png" ] && fail "CSG doubled: an image was written"
expect_status 0 "CSG doubled 25 times, --max-primitives 2^24 + 2" "$crtc" --check --max-primitives 16777218 "$work/csg.crt"
expect_status 1 "CSG doubled 25 times, --max-primitives 2^24 + 1" "$crtc" --check --max-primitives 16777217 "$work/csg.crt"

# A macro group doubled 20 times: 21 entities, 2^20 primitives.
printf '%s\ntwice = Macro (x) {\n    x\n    x\n}\ng = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nfor i in range(20) { g = twice(g) }\nScene { g }\n' \
    "$camera" >"$work/group.crt"
expect_status 1 "a group doubled 20 times, --max-primitives 1000" "$crtc" --check --max-entities 1000 --max-primitives 1000 "$work/group.crt"
expect_text "$work/err" "^$work/group.crt:8:9: error: the scene stores more than 1000 primitives" \
    "the doubled group: the error at the drawing"

# The drawn total. An entity of 8 primitives drawn 20 times is 20 copies of it: 160.
printf '%s\ng = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nfor i in range(3) { g = g + g }\nScene {\n    for i in range(20) { g }\n}\n' \
    "$camera" >"$work/drawn.crt"
expect_status 1 "20 draws of 8 primitives, --max-primitives 159" "$crtc" --check --max-primitives 159 "$work/drawn.crt"
expect_text "$work/err" "^$work/drawn.crt:5:26: error: the scene stores more than 159 primitives" "the drawn total: the error at the draw"
expect_status 0 "20 draws of 8 primitives, --max-primitives 160" "$crtc" --check --max-primitives 160 "$work/drawn.crt"

# One of 16 or more drawn again is stored once, each drawing one more: a forest of 10,000
# drawings of a 1,024-primitive tree stores 11,024 (10,240,000 as copies), for --check and
# for a render alike.
printf '%s\ntree = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nfor i in range(10) { tree = tree + tree }\nScene {\n    for i in range(10000) { tree <translate vec3(i, 0, 0)> }\n}\n' \
    "$camera" >"$work/forest.crt"
expect_status 0 "a forest of 10,000 trees of 1,024 primitives, --max-primitives 11024" "$crtc" --check --max-primitives 11024 "$work/forest.crt"
expect_status 1 "a forest of 10,000 trees of 1,024 primitives, --max-primitives 11023" "$crtc" --check --max-primitives 11023 "$work/forest.crt"
expect_text "$work/err" "^$work/forest.crt:5:29: error: the scene stores more than 11023 primitives" "the forest: the error at the last drawing"
expect_status 0 "the forest rendered with the default limit" "${limited[@]}" "$crtc" -o "$work/forest.png" "$work/forest.crt"

# Entities built and never drawn count: a loop making spheres it throws away.
printf '%s\nmake = Macro (i) { Sphere { center -> vec3(i, 0, 0) radius -> 1 } }\ni = 0\nwhile (i < 24000000) {\n    s = make(i)\n    i = i + 1\n}\nScene { s }\n' \
    "$camera" >"$work/undrawn.crt"
expect_status 1 "24,000,000 spheres never drawn, --max-entities 100000" "${limited[@]}" "$crtc" --check --max-entities 100000 "$work/undrawn.crt"
expect_text "$work/err" "^$work/undrawn.crt:2:20: error: the script builds more than 100000 entities \(drawn or not\); raise the limit with --max-entities$" \
    "undrawn spheres: the entity error at the literal"

# A mesh's triangles are stored once however often it is drawn, and each drawing is one
# primitive: three uses of a 4-triangle mesh are 4 + 3, for --check as for a render.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n' >"$work/tetra.obj"
printf '%s\nm = Mesh { file -> "tetra.obj" }\nScene { m m m }\n' "$camera" >"$work/mesh.crt"
for mode in --check "-o $work/mesh.png"; do
    # shellcheck disable=SC2086 # the mode is two words
    expect_status 1 "three meshes of 4 triangles, --max-primitives 6, $mode" "$crtc" $mode --max-primitives 6 "$work/mesh.crt"
    expect_text "$work/err" "^$work/mesh.crt:3:13: error: the scene stores more than 6 primitives" \
        "the mesh's drawings counted by $mode"
    # shellcheck disable=SC2086
    expect_status 1 "a mesh of 4 triangles, --max-primitives 3, $mode" "$crtc" $mode --max-primitives 3 "$work/mesh.crt"
    expect_text "$work/err" "^$work/mesh.crt:2:20: error: the scene stores more than 3 primitives with the 4 triangles of this mesh" \
        "the mesh's triangles counted by $mode"
done
expect_status 0 "three meshes of 4 triangles, --max-primitives 7" "$crtc" --max-primitives 7 -o "$work/mesh.png" "$work/mesh.crt"

# Images: the size in the header is refused before any pixel is decoded. A 30000 x 30000
# PNG (one bit a pixel, all zero: a few hundred KB) would decode to 13.5 GB of floats; so
# would a truncated one of a few hundred bytes.
python3 - "$work" <<'PY'
import struct, sys, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
def png(path, width, height, truncate):
    header = struct.pack(">IIBBBBB", width, height, 1, 0, 0, 0, 0)  # 1-bit grey
    row = bytes(1 + (width + 7) // 8)
    compressor = zlib.compressobj(9)
    data = b"".join(compressor.compress(row) for _ in range(height)) + compressor.flush()
    if truncate:
        data = data[:200]
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", data))
        if not truncate:
            f.write(chunk(b"IEND", b""))
png(sys.argv[1] + "/huge.png", 30000, 30000, False)
png(sys.argv[1] + "/truncated.png", 30000, 30000, True)
png(sys.argv[1] + "/small.png", 4, 4, False)
# A TIFF whose header claims 1000 x 1000 pixels of 1000 channels (RGB and 997 extra), with no
# pixel data: 4 KB that would take 5 GB to read.
width, height, channels = 1000, 1000, 1000
arrays_at = 8 + 2 + 10 * 12 + 4
bits = struct.pack("<%dH" % channels, *[8] * channels)
extra = struct.pack("<%dH" % (channels - 3), *[0] * (channels - 3))
entries = [(256, 4, 1, width), (257, 4, 1, height), (258, 3, channels, arrays_at),
           (259, 3, 1, 1), (262, 3, 1, 2), (273, 4, 1, 0), (277, 3, 1, channels),
           (278, 4, 1, height), (279, 4, 1, width * height * channels),
           (338, 3, channels - 3, arrays_at + len(bits))]
directory = struct.pack("<H", len(entries)) + b"".join(
    struct.pack("<HHII", tag, kind, count, value) for tag, kind, count, value in entries)
with open(sys.argv[1] + "/channels.tif", "wb") as f:
    f.write(b"II*\0" + struct.pack("<I", 8) + directory + struct.pack("<I", 0) + bits + extra)
PY
# The script asks for the image on line 2.
with_background() { # image
    printf 'Settings { width -> 8 height -> 8\n    background -> Background { image -> "%s" } }\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }\n' "$1"
}
for image in huge truncated; do
    with_background "$image.png" >"$work/$image.crt"
    expect_status 1 "a $image 30000 x 30000 PNG" "${limited[@]}" "$crtc" -o "$work/$image-out.png" "$work/$image.crt"
    expect_text "$work/err" "^$work/$image.crt:2:19: error: cannot read \"$work/$image.png\": it is 30000 x 30000 pixels, more than the 100000000 allowed; raise the limit with --max-image-pixels" \
        "the $image PNG: the image error"
    [ -e "$work/$image-out.png" ] && fail "the $image PNG: an image was written"
done
with_background channels.tif >"$work/channels.crt"
expect_status 1 "a TIFF of 1000 x 1000 pixels of 1000 channels" "${limited[@]}" "$crtc" -o "$work/channels-out.png" "$work/channels.crt"
expect_text "$work/err" "^$work/channels.crt:2:19: error: cannot read \"$work/channels.tif\": it is 1000 x 1000 pixels of 1000 channels, more values than the 100000000 pixels allowed hold at four channels each; raise the limit with --max-image-pixels" \
    "the 1000-channel TIFF: the image error"
[ -e "$work/channels-out.png" ] && fail "the 1000-channel TIFF: an image was written"
with_background small.png >"$work/small.crt"
expect_status 1 "a 4 x 4 PNG, --max-image-pixels 15" "$crtc" --max-image-pixels 15 -o "$work/small-out.png" "$work/small.crt"
expect_text "$work/err" "it is 4 x 4 pixels, more than the 15 allowed" "the small PNG over its limit"
expect_status 0 "a 4 x 4 PNG, --max-image-pixels 16" "$crtc" --max-image-pixels 16 -o "$work/small-out.png" "$work/small.crt"

finish
