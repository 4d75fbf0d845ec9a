#!/usr/bin/env bash
# One POV-Ray twin test: renders NAME.crt with crtc and NAME.pov with POV-Ray 3.7 (the same
# pattern with the same numbers, on the stage of stage.crt / stage.inc) and compares them.
#
# usage: povray_twin.sh CRTC POVRAY RENDER_COMPARE TWIN.crt
# The first line of TWIN.crt says the allowed RMSE in 8-bit codes: "-- rmse: 2".
# Exit status: 0 pass, 1 fail. A failing test keeps both renders in
# $CRT_RENDER_FAILURES (default /tmp/crt-render-failures).
set -u
crtc=$1 povray=$2 compare=$3 twin=$4
name=$(basename "$twin" .crt)
folder=$(cd "$(dirname "$twin")" && pwd)
size=200

if [ ! -x "$povray" ]; then
    echo "FAIL: POV-Ray is not at $povray; scripts/setup.sh installs it (Debian's povray)"
    exit 1
fi
rmse=$(sed -n '1s/^-- rmse: *\([0-9.]*\).*/\1/p' "$twin")
if [ -z "$rmse" ]; then
    echo "FAIL: $twin does not start with '-- rmse: CODES'"
    exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! "$crtc" -q --width $size --height $size --threads 2 -o "$work/crt.png" "$twin" >"$work/crt.log" 2>&1; then
    echo "FAIL: crtc could not render $twin:"
    head -20 "$work/crt.log"
    exit 1
fi
# POV-Ray writes only under its working folder and wants a home for its user settings.
mkdir -p "$work/home"
if ! (cd "$work" && HOME=$work/home "$povray" "+I$folder/$name.pov" "+L$folder" +Opov.png +FN \
        "+W$size" "+H$size" -D -V -P -GA File_Gamma=1.0 >pov.log 2>&1); then
    echo "FAIL: POV-Ray could not render $folder/$name.pov:"
    tail -20 "$work/pov.log"
    exit 1
fi
report=$("$compare" "$work/pov.png" "$work/crt.png" --rmse "$rmse")
status=$?
echo "$name: $report"
if [ $status != 0 ]; then
    failures=${CRT_RENDER_FAILURES:-/tmp/crt-render-failures}
    mkdir -p "$failures"
    cp "$work/crt.png" "$failures/povray_$name.crt.png"
    cp "$work/pov.png" "$failures/povray_$name.pov.png"
    echo "kept both renders in $failures/povray_$name.{crt,pov}.png"
fi
exit $status
