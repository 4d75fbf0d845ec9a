#!/usr/bin/env bash
# End-to-end test with a real client: headless Neovim (0.7 from Debian) drives crt-lsp through
# editors/nvim (syntax, mappings, :CrtPreview).
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
cat > "$work/syntax.crt" <<'CRT'
-- for the Scene: 2. "x" if
ball = Sphere { center -> vec3(0, 0, 0) radius -> 2. } -- é
Scene { ball }
print(2., .25, "a\tb \q", true, 1e3)
CRT
# :CrtPreview runs this in place of crtc: it prints what crtc --preview prints first, then
# serves until SIGTERM, which it records.
cat > "$work/fake-crtc" <<'SH'
#!/usr/bin/env bash
printf '%s\n' "$@" > "$CRT_FAKE_LOG"
trap 'touch "$CRT_FAKE_LOG.stopped"; exit 0' TERM
echo "preview: http://127.0.0.1:8123/?token=abc"
while :; do sleep 0.1; done
SH
chmod +x "$work/fake-crtc"
cd "$work"
HOME="$work/home" XDG_CACHE_HOME="$work/cache" XDG_STATE_HOME="$work/state" XDG_DATA_HOME="$work/data" \
CRT_LSP="$lsp" CRT_FILE="$work/scene.crt" CRT_SYNTAX_FILE="$work/syntax.crt" \
CRT_FAKE_CRTC="$work/fake-crtc" CRT_FAKE_LOG="$work/fake-crtc.log" CRT_EDITORS_NVIM="$here/../../../editors/nvim" \
    timeout 90 nvim --headless --clean -n -c "luafile $here/e2e.lua"
