#!/usr/bin/env bash
# Builds the VS Code extension: <repo>/dist/crt-<version>.vsix (or into OUT_DIR).
#   editors/vscode/package.sh [OUT_DIR]
# Installs the pinned npm devDependencies locally (install-deps.sh), bundles the client
# with esbuild into dist/extension.js (no node_modules in the package), copies the
# repository's LICENSE in, and runs vsce package. Fails on any vsce warning.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=$(mkdir -p "${1:-$root/dist}" && cd "${1:-$root/dist}" && pwd)
cd "$here"

if [ ! -f "$root/LICENSE" ]; then
    echo "package: $root/LICENSE is missing: the extension ships the repository's license" >&2
    exit 1
fi
./install-deps.sh
cp "$root/LICENSE" LICENSE

./node_modules/.bin/esbuild src/extension.js --bundle --platform=node --target=node18 \
    --format=cjs --external:vscode --minify --log-level=warning \
    --outfile=dist/extension.js

version=$(node -p 'require("./package.json").version')
vsix="$out/crt-$version.vsix"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# vsce warns on standard error and asks before going on: no input, and any warning fails.
./node_modules/.bin/vsce package --no-dependencies --out "$vsix" </dev/null >"$log" 2>&1 || {
    cat "$log" >&2
    exit 1
}
if grep -qi 'warning' "$log"; then
    cat "$log" >&2
    echo "package: vsce warned (above); fix the manifest rather than ignore it" >&2
    rm -f "$vsix"
    exit 1
fi
echo "package: $vsix"
