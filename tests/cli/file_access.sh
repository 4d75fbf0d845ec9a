#!/usr/bin/env bash
# What a script may read (docs/crtc.md, "File access"), and bytes of a script shown safely.
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}
run() { # expected-status description, then crtc's arguments; output in $work/out, $work/err
    local want=$1 what=$2
    shift 2
    timeout 20 "$crtc" "$@" >"$work/out" 2>"$work/err"
    local got=$?
    [ "$got" = "$want" ] || fail "$what: exit status $got, expected $want ($(head -3 "$work/err"))"
}
has() { # pattern description: in standard error
    grep -qE -- "$1" "$work/err" || fail "$2: no '$1' in: $(head -5 "$work/err")"
}
lacks() { # pattern description: not in standard error
    ! grep -qE -- "$1" "$work/err" || fail "$2: '$1' in: $(head -5 "$work/err")"
}

mkdir -p "$work/proj/sub" "$work/other" "$work/deep/scripts" "$work/deep/images" "$work/proj/images"
scene='Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }'
background() { printf 'Settings { background -> Background { image -> "%s" } }\n%s\n' "$1" "$scene"; }
printf 'P3\n1 1\n255\n255 0 0\n' >"$work/proj/images/sky.ppm"
cp "$work/proj/images/sky.ppm" "$work/deep/images/sky.ppm"
cp "$work/proj/images/sky.ppm" "$work/other/sky.ppm"

# --- Outside the roots: refused at the string that names it, whether or not the file exists, and
# nothing of it is shown.
printf 'include "/etc/passwd"\n' >"$work/proj/abs.crt"
run 1 "include of /etc/passwd" --check "$work/proj/abs.crt"
has 'abs.crt:1:9: error: cannot include "/etc/passwd": it is outside the folders a script may read' "absolute include"
has 'allow it with --allow-read DIR \(or --allow-read-all\)' "the refusal names the options"
lacks 'root:' "/etc/passwd's lines"
printf 'include "../../../../../../../../../../etc/passwd"\n' >"$work/proj/rel.crt"
run 1 "include of ../../etc/passwd" --check "$work/proj/rel.crt"
has 'rel.crt:1:9: error: cannot include ".*etc/passwd": it is outside' "relative include"
lacks 'root:' "/etc/passwd's lines (relative)"
printf 'include "/etc/no-such-file-here"\n' >"$work/proj/absent.crt"
run 1 "include of a missing file outside" --check "$work/proj/absent.crt"
has 'it is outside the folders' "a missing file outside is refused alike: no existence oracle"

background /etc/hostname >"$work/proj/image.crt"
run 1 "an image outside the roots" --check "$work/proj/image.crt"
has 'image.crt:1:48: error: cannot find image "/etc/hostname" in the script.s folder or those above it; as an absolute path, it is outside' "image outside"
printf 'Scene { Mesh { file -> "/proc/self/maps" } }\n' >"$work/proj/mesh.crt"
run 1 "a mesh outside the roots" --check "$work/proj/mesh.crt"
has 'mesh.crt:1:24: error: cannot find mesh "/proc/self/maps".*outside' "mesh outside"
# A font as an image: refused outside the roots, even DejaVu's (the default is not refused).
printf 'Scene { Text { text -> "a" font -> "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" } }\n' >"$work/proj/font.crt"
run 1 "a font outside the roots" --check "$work/proj/font.crt"
has 'font.crt:1:36: error: cannot find font "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".*outside' "font outside"
printf 'Scene { Text { text -> "a" } }\n' >"$work/proj/default-font.crt"
run 0 "the default font" --check "$work/proj/default-font.crt"
background ../other/sky.ppm >"$work/proj/up.crt"
run 1 "an image in a sibling folder" --check "$work/proj/up.crt"
has 'error: image ".*other/sky.ppm" is outside the folders' "relative image outside"
run 0 "--allow-read lets a folder be read" --check --allow-read "$work/other" "$work/proj/up.crt"
# Refused alike when it does not exist, by a relative name or a "/..." name that climbs out.
background ../other/no-such.ppm >"$work/proj/up-missing.crt"
run 1 "a missing image in a sibling folder" --check "$work/proj/up-missing.crt"
has 'error: image ".*other/no-such.ppm" is outside the folders' "relative missing image outside: no existence oracle"
background /../../../../../../../../etc/no-such-file >"$work/proj/climb.crt"
run 1 "a /... name that climbs out with .." --check "$work/proj/climb.crt"
has 'error: image ".*etc/no-such-file" is outside the folders' "climbing /... name: no existence oracle"

# A missing file is one line, not every parent folder.
background /nothere/x.ppm >"$work/proj/missing.crt"
run 1 "a missing image" --check "$work/proj/missing.crt"
[ "$(grep -c . "$work/err")" = 3 ] || fail "a missing image's error is not one diagnostic: $(cat "$work/err")"
lacks "^  /" "no folder list"

# --- A symbolic link out of the folder is followed before the check.
printf 'inside = 1\n' >"$work/other/lib.crt"
ln -s ../other/lib.crt "$work/proj/link.crt"
printf 'include "link.crt"\nScene { Sphere { center -> vec3(0, 0, inside) radius -> 1 } }\n' >"$work/proj/linked.crt"
run 1 "an include through a link out of the folder" --check "$work/proj/linked.crt"
has 'cannot include "link.crt": it is outside' "link escaping"
run 0 "--allow-read of the link's target" --check --allow-read "$work/other" "$work/proj/linked.crt"
run 0 "-I counts as a root" --check -I "$work/other" "$work/proj/linked.crt"

# --- "/..." names: searched in the script's folder and those above it; only the roots are read.
background /images/sky.ppm >"$work/proj/slash.crt"
run 0 "/images/... in the script's own folder" --check "$work/proj/slash.crt"
background /images/sky.ppm >"$work/deep/scripts/slash.crt"
run 1 "/images/... found above the script's folder" --check "$work/deep/scripts/slash.crt"
has 'image ".*deep/images/sky.ppm" is outside the folders' "found above: named and refused"
run 0 "--assets makes it a root" --check --assets "$work/deep" "$work/deep/scripts/slash.crt"

# --- Folders, FIFOs, devices: refused with the reason, never opened (a FIFO would block).
printf 'include "sub"\n' >"$work/proj/folder.crt"
run 1 "include of a folder" --check "$work/proj/folder.crt"
has 'cannot include "sub": it is a folder, not a file' "folder"
mkfifo "$work/proj/pipe.crt"
printf 'include "pipe.crt"\n' >"$work/proj/fifo.crt"
run 1 "include of a FIFO" --check "$work/proj/fifo.crt"
has 'cannot include "pipe.crt": it is a FIFO' "FIFO"
background /dev/zero >"$work/proj/device.crt"
run 1 "an image that is a device" --check --allow-read-all "$work/proj/device.crt"
has '"/dev/zero".* it is a device, not a file' "device"

# --- --allow-read-all: the old rule; a file that is not a script is still not shown.
run 1 "--allow-read-all reads /etc/passwd" --check --allow-read-all "$work/proj/abs.crt"
lacks 'outside the folders' "--allow-read-all"
has '^/etc/passwd:1:[0-9]+: error' "the allowed include's errors"
lacks 'root:' "the lines of an included file that is not a .crt file"
printf 'include "%s"\n' "$(command -v ls)" >"$work/proj/binary.crt"
run 1 "include of a binary" --check --allow-read-all "$work/proj/binary.crt"
has 'it is not a CRT script \(it holds NUL bytes or invalid UTF-8\)' "binary include"
[ "$(wc -c <"$work/err")" -lt 1000 ] || fail "a binary include printed $(wc -c <"$work/err") bytes"

# --- Bytes of a script reach the terminal escaped; carets still line up.
esc=$(printf '\033')
printf 'x\033]0;pwned\007 = 1\n' >"$work/proj/ident.crt"
run 1 "an escape sequence in an identifier" --check --color never "$work/proj/ident.crt"
grep -qF '    x\x1b]0;pwned\x07 = 1' "$work/err" || fail "the source line is not escaped: $(cat -A "$work/err" | head -3)"
grep -qxF '     ^~~~' "$work/err" || fail "the caret under \\x1b: $(head -4 "$work/err")"
grep -qxF '                 ^~~~' "$work/err" || fail "the caret under \\x07: $(cat "$work/err")"
printf 's = Sphere { center -> vec3(0, 0, 0) radius -> "a\033[2J\342\200\256b" }\nScene { s }\n' >"$work/proj/string.crt"
run 1 "an escape sequence in a string" --check --color always "$work/proj/string.crt"
grep -qF '"a\x1b[2J\u202eb"' "$work/err" || fail "the string is not escaped: $(cat -A "$work/err")"
grep -qF "$esc[1m" "$work/err" || fail "--color always lost its own colours"
grep -q "$esc\[2J" "$work/err" && fail "the script's ESC reached the terminal"
grep -q "$(printf '\342\200\256')" "$work/err" && fail "a bidi override reached the terminal"
printf 'include "\033[31mred\377.crt"\n' >"$work/proj/name.crt"
run 1 "an escape sequence in an include name" --check --color never "$work/proj/name.crt"
has 'cannot find include file "\\x1b\[31mred\\xff\.crt"' "include name escaped in the message"
grep -q "$esc" "$work/err" && fail "an ESC reached the terminal through a message"
printf 'v 0 0 0\nv 1 \033[2J 0\n' >"$work/proj/bad.obj"
printf 'Scene { Mesh { file -> "bad.obj" } }\n' >"$work/proj/obj.crt"
run 1 "an escape sequence in an OBJ token" -q -o "$work/obj.png" "$work/proj/obj.crt"
has "bad mesh 'bad.obj': bad number '\\\\x1b\[2J'" "OBJ token escaped in the message"
has "^    v 1 \\\\x1b\[2J 0\$" "OBJ line escaped where the note quotes it"
printf 'print("a\033[2Jb")\n%s\n' "$scene" >"$work/proj/print.crt"
run 0 "print() into a pipe" --check "$work/proj/print.crt"
grep -q "a$esc\[2Jb" "$work/out" || fail "print() into a pipe changed the script's output"

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all file-access checks passed"
