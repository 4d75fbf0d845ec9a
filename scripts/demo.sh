#!/usr/bin/env bash
# Sets everything up, builds, and renders a demo scene to build/demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
demo=${1:-demos/piano_foot.crt}
echo "== crtc --check $demo"
build/bin/crtc --check "$demo"
echo "== crtc $demo -o build/demo.png"
build/bin/crtc "$demo" -o build/demo.png --stats
echo "== wrote build/demo.png"
