#!/usr/bin/env bash
# crtc on a full disk, for every output format: status 2, the previous file intact, no temporary.
# Needs root, to mount a 1 MB tmpfs; skipped (77) otherwise.
set -u
crtc=$1
if [ "$(id -u)" != 0 ]; then
    echo "SKIP: mounting a small tmpfs to fill needs root"
    exit 77
fi
work=$(mktemp -d)
disk=$work/disk
mkdir "$disk"
if ! mount -t tmpfs -o size=1m crt-full-disk-test "$disk"; then
    rmdir "$disk"
    rm -rf "$work"
    echo "SKIP: cannot mount a tmpfs here (a container without the capability?)"
    exit 77
fi
trap 'umount "$disk"; rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

cat >"$work/scene.crt" <<'CRT'
Settings { lights -> [PointLight { origin -> vec3(2, 4, -3) color -> rgb(1, 1, 1) }] }
Scene { Sphere { center -> vec3(0, 0, 3) radius -> 1 } }
CRT

# The previous outputs, written while there is room; then the disk is filled to the last block.
outputs="old.png old.jpg old.tif old.exr old.hdr old.gif old00.png old01.png old00.jpg old01.jpg"
for name in old.png old.jpg old.tif old.exr old.hdr; do
    "$crtc" -q --width 8 --height 8 -o "$disk/$name" "$work/scene.crt" || fail "writing $name while there is room"
done
"$crtc" -q --width 8 --height 8 --frames 2 -o "$disk/old.gif" "$work/scene.crt" || fail "writing old.gif"
for ext in png jpg; do
    "$crtc" -q --width 8 --height 8 --frames 2 -o "$disk/old%02d.$ext" "$work/scene.crt" ||
        fail "writing numbered .$ext frames"
done
for name in $outputs; do cp "$disk/$name" "$work/$name.before"; done
dd if=/dev/zero of="$disk/filler" bs=4096 2>/dev/null
dd if=/dev/zero of="$disk/filler.last" bs=1 2>/dev/null

check_run() { # description, then crtc's arguments
    local what=$1
    shift
    "$crtc" -q --width 300 --height 300 "$@" "$work/scene.crt" 2>"$work/err"
    local status=$?
    [ "$status" = 2 ] || fail "$what: exit status $status on a full disk, expected 2 ($(head -2 "$work/err"))"
    grep -q "^crtc: " "$work/err" || fail "$what: no message"
    for name in $outputs; do
        cmp -s "$disk/$name" "$work/$name.before" || fail "$what: $name changed"
    done
    local temporaries
    temporaries=$(find "$disk" -name '.*' -type f | head -3)
    [ -z "$temporaries" ] || fail "$what: temporaries left: $temporaries"
    rm -f "$disk"/.*.tmp
}
for ext in png jpg tif exr hdr; do check_run ".$ext" -o "$disk/old.$ext"; done
check_run "an animated GIF" --frames 2 -o "$disk/old.gif"
check_run "numbered PNG frames" --frames 2 -o "$disk/old%02d.png"
check_run "numbered JPEG frames" --frames 2 -o "$disk/old%02d.jpg"

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all full-disk checks passed"
