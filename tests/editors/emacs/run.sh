#!/usr/bin/env bash
# End-to-end test of editors/emacs: batch Emacs (Debian's emacs-nox with elpa-eglot) opens
# scripts in crt-mode (faces, comments, indentation) and, through Eglot, gets a diagnostic,
# hover, completion and formatting from crt-lsp.
#   run.sh CRT_LSP
# Exits 77 (skipped) when emacs or eglot is not installed.
set -euo pipefail
lsp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v emacs >/dev/null 2>&1; then
    echo "skipped: emacs is not installed (apt-get install emacs-nox elpa-eglot)"
    exit 77
fi
if ! emacs -Q --batch --eval "(progn (require 'package) (setq package-directory-list '(\"/usr/share/emacs/site-lisp/elpa\")) (package-initialize) (require 'eglot))" 2>/dev/null; then
    echo "skipped: eglot is not installed (apt-get install elpa-eglot)"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home"
cat > "$work/syntax.crt" <<'CRT'
-- for the Scene: 2. "x" if
ball = Sphere { center -> vec3(0, 0, 0) radius -> 2. }
Scene { ball }
print(2., "a\tb", true) -- done
CRT
cat > "$work/indent.crt" <<'CRT'
bump = Macro (n) {
    s = 0
    for i in range(n) {
        s = s + [
            1,
            2
        ][i % 2]
    }
    s
}
Scene {
    Sphere {
        center -> vec3(0, bump(3), 0)
        radius -> 1
    } <scale 2>
}
CRT
cat > "$work/scene.crt" <<'CRT'
-- été: the error below sits after non-ASCII text on its line
ball = Sphere { center -> vec3(0, 0, 0) radus -> 1 } -- é
CRT
cd "$work"
HOME="$work/home" CRT_LSP="$lsp" CRT_EDITORS_EMACS="$here/../../../editors/emacs" CRT_WORK="$work" \
    timeout 120 emacs -Q --batch -l "$here/e2e.el"
