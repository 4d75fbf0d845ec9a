#!/usr/bin/env bash
# Sets everything up, builds, and runs crtc on a demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
demo=demos/mirror_hall.crt
echo "== crtc --check $demo"
build/lang/crtc --check "$demo"
echo "== crtc --dump-scene $demo (first lines)"
build/lang/crtc --dump-scene "$demo" | head -n 40
echo "== ok: $(build/lang/crtc --dump-scene "$demo" | grep -c '"id"') entities evaluated"
