#!/usr/bin/env bash
# One render regression test: renders a scene with the real crtc and compares it with its reference.
#
# usage: render_test.sh CRTC RENDER_COMPARE SCENE REFERENCE [crtc options...]
# Exit status: 0 pass, 1 fail, 77 skipped (the scene's folder is absent, e.g. ../shared/conformance).
# With CRT_UPDATE_REFERENCES=1 (set by scripts/update_render_references.sh) a missing reference, or
# one the render no longer matches within the tolerance, is replaced by the new render; with
# CRT_UPDATE_REFERENCES=all any pixel difference replaces it. CRT_UPDATE_LOG names a file that
# collects one line per scene for the update script's summary.
set -u
crtc=$1 compare=$2 scene=$3 reference=$4
shift 4
update=${CRT_UPDATE_REFERENCES:-}
log=${CRT_UPDATE_LOG:-/dev/null}

if [ ! -d "$(dirname "$scene")" ]; then
    echo "SKIP: folder $(dirname "$scene") is absent (set CRT_CONFORMANCE_DIR to the conformance scripts)"
    exit 77
fi
if [ ! -f "$scene" ]; then
    echo "SKIP: scene $scene is absent"
    exit 77
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/render.png
start=$(date +%s%N)
"$crtc" -q "$@" -o "$out" "$scene" >"$work/log" 2>&1
status=$?
milliseconds=$((($(date +%s%N) - start) / 1000000))
if [ "$status" != 0 ] || [ ! -f "$out" ]; then
    echo "FAIL: crtc $* -o $out $scene exited with status $status:"
    head -20 "$work/log"
    echo "FAILED $reference (crtc exit $status)" >>"$log"
    exit 1
fi
echo "rendered $scene with: $* (${milliseconds} ms)"

if [ ! -f "$reference" ]; then
    if [ -n "$update" ]; then
        mkdir -p "$(dirname "$reference")"
        cp "$out" "$reference"
        echo "NEW reference $reference"
        echo "NEW       $reference" >>"$log"
        exit 0
    fi
    echo "FAIL: no reference image $reference"
    echo "  create it with scripts/update_render_references.sh, then review it (tests/render/README.md)"
    exit 1
fi

report=$("$compare" "$reference" "$out")
status=$?
echo "$report"
verdict=${report%%:*}
if [ -n "$update" ]; then
    if [ "$status" = 2 ]; then
        echo "FAILED    $reference (cannot compare)" >>"$log"
        exit 1
    fi
    if [ "$status" = 1 ] || { [ "$update" = all ] && [ "$verdict" != IDENTICAL ]; }; then
        cp "$out" "$reference"
        echo "UPDATED   $reference: $report" >>"$log"
    else
        echo "KEPT      $reference: $report" >>"$log"
    fi
    exit 0
fi
if [ "$status" != 0 ]; then
    echo "FAIL: the render differs from $reference beyond the tolerance"
    mkdir -p "${CRT_RENDER_FAILURES:-/tmp/crt-render-failures}"
    keep="${CRT_RENDER_FAILURES:-/tmp/crt-render-failures}/$(basename "$(dirname "$reference")")_$(basename "$reference")"
    cp "$out" "$keep" && echo "  the new render is kept as $keep"
    exit 1
fi
exit 0
