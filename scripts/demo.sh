#!/usr/bin/env bash
# Sets everything up, builds crtc and its image module (not the tests), and renders a demo
# scene to build/demo.png.
#   scripts/demo.sh [scene.crt]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target crtc crt_image_io_oiio
demo=${1:-demos/piano_foot.crt}
echo "== crtc --check $demo"
build/bin/crtc --check "$demo"
echo "== crtc $demo -o build/demo.png"
build/bin/crtc "$demo" -o build/demo.png --stats
echo "== wrote build/demo.png"
