#!/usr/bin/env bash
# Installs the pinned devDependencies of package-lock.json into editors/vscode/node_modules
# (npm's cache in editors/vscode/.npm-cache; nothing global). Quick when they are there.
# Exits 77 when the npm registry cannot be reached (the tests read that as "skipped").
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
if ! command -v npm >/dev/null 2>&1; then
    echo "install-deps: npm is not installed (apt-get install npm)" >&2
    exit 77
fi
# One installer at a time: tests run in parallel share this folder.
exec 9>"$here/.install.lock"
flock 9
# npm writes node_modules/.package-lock.json: every locked package at its locked version
# means there is nothing to do.
if [ -f node_modules/.package-lock.json ] && node -e '
    const wanted = require("./package-lock.json").packages;
    const installed = require("./node_modules/.package-lock.json").packages;
    for (const [name, entry] of Object.entries(wanted)) {
        if (name && !entry.optional && installed[name]?.version !== entry.version) process.exit(1);
    }' 2>/dev/null; then
    exit 0
fi
if ! npm ping --cache "$here/.npm-cache" >/dev/null 2>&1; then
    echo "install-deps: the npm registry cannot be reached" >&2
    exit 77
fi
npm ci --cache "$here/.npm-cache" --no-audit --no-fund --loglevel=error >&2
