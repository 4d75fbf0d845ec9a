#!/usr/bin/env bash
# `cmake --install` into a temporary prefix gives a working crt (check_installed.sh), which
# reads nothing from the source or build tree: without the standard library or the image
# module installed beside it, the installed crtc fails and says where it looked.
#   install_prefix.sh BUILD_DIR SOURCE_DIR PYTHON
set -u
source "$(dirname "$0")/common.sh"
build=$1 source_dir=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v man >/dev/null 2>&1; then
    echo "skipped: man is not installed (scripts/setup.sh installs man-db)"
    exit 77
fi
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT

if ! cmake --install "$build" --prefix "$prefix" >"$prefix.log" 2>&1; then
    cat "$prefix.log"
    rm -f "$prefix.log"
    echo "FAIL: cmake --install $build --prefix $prefix"
    exit 1
fi
rm -f "$prefix.log"
bash "$here/check_installed.sh" "$prefix" "$build/bin/crtc" "$source_dir" "$python" || fail "check_installed.sh"

scene=$prefix/share/doc/crt/examples/piano_foot.crt # includes colors.crt
mv "$prefix/share/crt/stdlib" "$prefix/stdlib.away"
run_installed "$prefix/bin/crtc" --check "$scene" >/dev/null 2>"$prefix/err"
status=$?
[ $status -eq 1 ] || fail "without the installed standard library, crtc --check exited $status, not 1"
grep -q "cannot find include file \"colors.crt\"" "$prefix/err" ||
    fail "without the installed standard library: $(cat "$prefix/err")"
grep -q "$source_dir/stdlib" "$prefix/err" && fail "the installed crtc searched the source tree's stdlib"
mv "$prefix/stdlib.away" "$prefix/share/crt/stdlib"

mv "$prefix/lib/crt/crt_image_io_oiio.so" "$prefix/module.away"
run_installed "$prefix/bin/crtc" "$scene" --width 8 --height 6 -q -o "$prefix/out.jpg" 2>"$prefix/err"
status=$?
[ $status -eq 2 ] || fail "without the installed image module, a JPEG render exited $status, not 2"
grep -q "$prefix/lib/crt/crt_image_io_oiio.so" "$prefix/err" ||
    fail "without the installed image module: $(cat "$prefix/err")"
[ -e "$prefix/out.jpg" ] && fail "a JPEG was written without the image module"

finish "install into a prefix"
