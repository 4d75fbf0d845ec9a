#!/usr/bin/env bash
# The VS Code extension's tests, with node and npm only (no VS Code):
#   run.sh grammar         the TextMate grammar on the annotated scripts in grammar/
#   run.sh extension CRTC  activation, settings, Render and Preview under a stubbed vscode
#                          module, and the problem matcher on the real crtc's output
#   run.sh package         editors/vscode/package.sh: the .vsix holds the bundle and what
#                          the marketplace page shows, nothing else, with no vsce warning
# The pinned npm packages are installed into editors/vscode/node_modules first; exits 77
# (skipped) when node, npm or the npm registry is not there.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
extension="$here/../../../editors/vscode"
if ! command -v node >/dev/null 2>&1; then
    echo "skipped: node is not installed (apt-get install nodejs npm)"
    exit 77
fi
status=0
"$extension/install-deps.sh" || status=$?
if [ "$status" -ne 0 ]; then
    [ "$status" -eq 77 ] && echo "skipped: the extension's npm packages cannot be installed"
    exit "$status"
fi
case "$1" in
grammar)
    # The grammar package.json contributes, found through package.json as VS Code does.
    cd "$extension"
    ./node_modules/.bin/vscode-tmgrammar-test --config package.json "$here/grammar/*.crt"
    ;;
extension)
    CRTC=$(realpath "$2") node --test "$here"
    ;;
package)
    if [ ! -f "$here/../../../LICENSE" ]; then
        echo "skipped: the repository has no LICENSE file for the package to ship"
        exit 77
    fi
    out=$(mktemp -d)
    trap 'rm -rf "$out"' EXIT
    "$extension/package.sh" "$out"
    version=$(node -p "require('$extension/package.json').version")
    mkdir "$out/unpacked"
    (cd "$out/unpacked" && unzip -q "$out/crt-$version.vsix")
    node "$here/package_check.js" "$out/unpacked"
    ;;
*)
    echo "usage: run.sh grammar | extension CRTC | package" >&2
    exit 2
    ;;
esac
