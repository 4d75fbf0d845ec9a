#!/usr/bin/env bash
# Renders the README gallery into docs/gallery/: every demo, and the original CRT's
# conformance scripts when ../shared/conformance is present (skipped otherwise).
#   scripts/render_gallery.sh [path/to/crtc]
set -euo pipefail
cd "$(dirname "$0")/.."
crtc="${1:-build/bin/crtc}"
out=docs/gallery
mkdir -p "$out"
render() { # script output [options...]
    local script=$1 target=$2
    shift 2
    echo "== $script -> $target"
    "$crtc" "$script" -o "$target" --width 400 --height 300 "$@"
}
for demo in demos/*.crt; do
    name=$(basename "$demo" .crt)
    if grep -q -- "--frames" "$demo"; then
        render "$demo" "$out/$name.gif" --frames 24
    else
        render "$demo" "$out/$name.png"
    fi
done
conformance=../shared/conformance
if [ -d "$conformance" ]; then
    for script in "$conformance"/*.crt; do
        name=$(basename "$script" .crt)
        if [[ $name == *Animation ]]; then
            render "$script" "$out/$name.gif" --frames 20
        else
            render "$script" "$out/$name.png"
        fi
    done
else
    echo "== $conformance is absent: conformance renders skipped"
fi
