#!/usr/bin/env bash
# End-to-end test with a real client: headless Neovim (0.7 from Debian) drives crt-lsp.
#   run.sh CRT_LSP
# Exits 77 (skipped) when nvim is not installed.
set -euo pipefail
lsp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v nvim >/dev/null 2>&1; then
    echo "skipped: nvim is not installed (apt-get install neovim)"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home" "$work/cache" "$work/state" "$work/data"
cat > "$work/lib.crt" <<'CRT'
gold = Material { color -> rgb(1, 0.8, 0.3) reflectivity -> 0.5 }
CRT
cat > "$work/scene.crt" <<'CRT'
include "lib.crt"
-- été: the error below sits after non-ASCII text on its line
ball = Sphere { center -> vec3(0, 0, 0) radus -> 1 material -> gold } -- é
Scene { ball }
CRT
cd "$work"
HOME="$work/home" XDG_CACHE_HOME="$work/cache" XDG_STATE_HOME="$work/state" XDG_DATA_HOME="$work/data" \
CRT_LSP="$lsp" CRT_FILE="$work/scene.crt" CRT_EDITORS_NVIM="$here/../../../editors/nvim" \
    timeout 90 nvim --headless --clean -n -c "luafile $here/e2e.lua"
