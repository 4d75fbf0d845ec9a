#!/usr/bin/env bash
# Re-renders the render regression scenes (tests/render) and replaces the references that changed.
#
# usage: scripts/update_render_references.sh [BUILD_DIR] [--all]
#   BUILD_DIR  a configured build tree (default: build)
#   --all      replace every reference whose pixels differ at all, not only those outside the
#              tolerance (2/255 per channel on 99.5% of pixels)
# Then review the replaced images before committing them (tests/render/README.md).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=build
mode=1
for arg in "$@"; do
    case $arg in
    --all) mode=all ;;
    -h | --help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) build=$arg ;;
    esac
done
case $build in /*) ;; *) build=$root/$build ;; esac
[ -f "$build/CMakeCache.txt" ] || { echo "update_render_references: $build is not a configured build tree" >&2; exit 2; }

cmake --build "$build" --target crtc render_compare crt_image_io_oiio
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
CRT_UPDATE_REFERENCES=$mode CRT_UPDATE_LOG=$log ctest --test-dir "$build" -R '^render/' -j2 --output-on-failure || status=$?

echo
echo "Render references (tests/render/references):"
sort -b -k2,2 "$log" | sed "s|$root/||"
if grep -qE '^(NEW|UPDATED)' "$log"; then
    echo
    echo "Review every NEW or UPDATED image before committing it, e.g.:"
    echo "  git -C $root status --short tests/render/references"
    echo "  git -C $root diff --stat tests/render/references"
    echo "and compare old and new side by side (tests/render/README.md)."
else
    echo "No reference changed."
fi
exit $status
